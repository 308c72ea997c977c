# Runs adaptivert-view with a script and --screenshot, then checks the screenshot against a
# committed baseline with `adaptivert compare`. Needs an X display (CI: xvfb-run -a); without
# one it prints "skipped" (the test's SKIP_REGULAR_EXPRESSION). Time-boxed.
include("${CMAKE_CURRENT_LIST_DIR}/../../../cmake/CompareWithBaseline.cmake")
if(NOT DEFINED ENV{DISPLAY} OR "$ENV{DISPLAY}" STREQUAL "")
  message(STATUS "no DISPLAY: skipped (run under xvfb-run -a)")
  return()
endif()
file(REMOVE "${OUT}")
string(REPLACE "|" ";" ARGS "${ARGS}")
execute_process(COMMAND ${VIEW} ${ARGS} --script ${SCRIPT} --screenshot ${OUT}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 90)
if(NOT rc EQUAL 0 OR NOT EXISTS "${OUT}")
  message(FATAL_ERROR "adaptivert-view failed (${rc}):\n${out}\n${err}")
endif()
art_compare_with_baseline("${ART}" "${OUT}" "${BASELINE}" ${MIN_PSNR} ${MIN_SSIM})
