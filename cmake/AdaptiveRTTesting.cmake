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
