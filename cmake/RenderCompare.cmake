# Renders with the CLI, then checks the image against a committed baseline (see
# art_render_baseline_test). -DART=<adaptivert> -DARGS=a|b|c -DOUT=<png> -DBASELINE=<png>
# -DMIN_PSNR=dB -DMIN_SSIM=s
include("${CMAKE_CURRENT_LIST_DIR}/CompareWithBaseline.cmake")
string(REPLACE "|" ";" ARGS "${ARGS}")
get_filename_component(_dir "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${_dir}")
execute_process(COMMAND "${ART}" render ${ARGS} -o "${OUT}" -q RESULT_VARIABLE rc OUTPUT_VARIABLE out
  ERROR_VARIABLE err TIMEOUT 300)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render failed (${rc}):\n${out}\n${err}")
endif()
art_compare_with_baseline("${ART}" "${OUT}" "${BASELINE}" ${MIN_PSNR} ${MIN_SSIM})
