# Helpers for ctest: GoogleTest executables, Python tests run by Debian's interpreter,
# and CLI checks. Labels: unit, image, stability, python, slow.
include(GoogleTest)

set(ART_SHARED_DATA "${CMAKE_SOURCE_DIR}/../shared/data" CACHE PATH
  "Development data (../shared/data); tests that need it are skipped when absent")
set(ART_TEST_OUTPUT "${CMAKE_BINARY_DIR}/Testing/Temporary")

# art_add_gtest(<name> SOURCES ... LINK ... [LABELS ...])
function(art_add_gtest name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;LINK;LABELS")
  if(NOT arg_LABELS)
    set(arg_LABELS unit)
  endif()
  add_executable(${name} ${arg_SOURCES})
  target_link_libraries(${name} PRIVATE ${arg_LINK} GTest::gtest GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    ART_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
    ART_SHARED_DATA="${ART_SHARED_DATA}"
    ART_TEST_OUTPUT="${ART_TEST_OUTPUT}")
  gtest_discover_tests(${name}
    DISCOVERY_MODE PRE_TEST
    TEST_PREFIX "${name}."
    PROPERTIES LABELS "${arg_LABELS}")
endfunction()

# art_add_python_test(<name> <script> [LABELS ...])
function(art_add_python_test name script)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "LABELS")
  add_test(NAME ${name} COMMAND "${Python3_EXECUTABLE}" "${script}")
  set_tests_properties(${name} PROPERTIES
    LABELS "python;${arg_LABELS}"
    ENVIRONMENT "PYTHONPATH=${ART_PYTHONPATH};ART_SOURCE_DIR=${CMAKE_SOURCE_DIR};ART_SHARED_DATA=${ART_SHARED_DATA};ART_TEST_OUTPUT=${ART_TEST_OUTPUT};ART_BIN=${CMAKE_BINARY_DIR}/bin")
endfunction()

# An image regression test (F3D style): `adaptivert render ARGS -o OUT`, then `adaptivert compare`
# against tests/baselines/BASELINE with PSNR and SSIM floors (cmake/RenderCompare.cmake).
function(art_render_baseline_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "BASELINE;MIN_PSNR;MIN_SSIM" "ARGS")
  string(REPLACE ";" "|" _args "${arg_ARGS}") # the script splits on |
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} "-DART=$<TARGET_FILE:adaptivert>" "-DARGS=${_args}"
    "-DOUT=${ART_TEST_OUTPUT}/${arg_BASELINE}" "-DBASELINE=${CMAKE_SOURCE_DIR}/tests/baselines/${arg_BASELINE}"
    "-DMIN_PSNR=${arg_MIN_PSNR}" "-DMIN_SSIM=${arg_MIN_SSIM}"
    -P "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/RenderCompare.cmake")
  set_tests_properties(${name} PROPERTIES LABELS image)
endfunction()

# A command-line check, F3D style (apps/adaptivert/Testing/expect.cmake runs one command and asserts its exit
# code and what it prints): art_expect_test(<test name> [PROGRAM <exe>] EXIT <code>
# [STDOUT <regex>] [STDERR <regex>] [ONE_LINE_STDERR] [LABELS ..] ARGS ...). PROGRAM defaults to
# the adaptivert tool, LABELS to unit.
# Runs `test` only after removing `dir`, the output a run before left (a batch's finished frames
# would otherwise count as done): a setup test <test>_clean and its fixture.
function(art_clean_first test dir)
  add_test(NAME ${test}_clean COMMAND ${CMAKE_COMMAND} -E rm -rf "${dir}")
  set_tests_properties(${test}_clean PROPERTIES FIXTURES_SETUP ${test}_clean LABELS unit)
  set_tests_properties(${test} PROPERTIES FIXTURES_REQUIRED ${test}_clean)
endfunction()

function(art_expect_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "ONE_LINE_STDERR" "PROGRAM;EXIT;STDOUT;STDERR" "ARGS;LABELS")
  if(NOT arg_PROGRAM)
    set(arg_PROGRAM "$<TARGET_FILE:adaptivert>")
  endif()
  if(NOT arg_LABELS)
    set(arg_LABELS unit)
  endif()
  string(REPLACE ";" "|" _args "${arg_ARGS}") # expect.cmake splits on |
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND}
    "-DCMD=${arg_PROGRAM}" "-DARGS=${_args}" "-DEXIT=${arg_EXIT}"
    "-DSTDOUT=${arg_STDOUT}" "-DSTDERR=${arg_STDERR}" "-DONE_LINE=${arg_ONE_LINE_STDERR}"
    -P "${CMAKE_SOURCE_DIR}/apps/adaptivert/Testing/expect.cmake")
  set_tests_properties(${name} PROPERTIES LABELS "${arg_LABELS}")
endfunction()
