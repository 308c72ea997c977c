# Renders with the CLI, then checks the image against a committed baseline with
# `adaptivert compare` (F3D style). ARGS are |-separated render arguments; OUT the image.
string(REPLACE "|" ";" ARGS "${ARGS}")
execute_process(COMMAND ${CMD} render ${ARGS} -o ${OUT} -q RESULT_VARIABLE rc OUTPUT_VARIABLE out
  ERROR_VARIABLE err TIMEOUT 300)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render failed (${rc}):\n${out}\n${err}")
endif()
message(STATUS "${out}")
execute_process(COMMAND ${CMD} compare ${OUT} ${BASELINE} --min-psnr ${MIN_PSNR} --min-ssim ${MIN_SSIM}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "image differs from ${BASELINE} (${rc}):\n${out}\n${err}")
endif()
