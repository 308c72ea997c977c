# Renders with the CLI, then checks the image against a committed baseline with `adaptivert compare`
# (F3D style). -DART=<adaptivert> -DOUT=<png> -DBASELINE=<png> -DRENDER_ARGS=a|b|c -DCOMPARE_ARGS=a|b
string(REPLACE "|" ";" _render "${RENDER_ARGS}")
string(REPLACE "|" ";" _compare "${COMPARE_ARGS}")
get_filename_component(_dir "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${_dir}")
execute_process(COMMAND "${ART}" render ${_render} -o "${OUT}" --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render failed (${rc}): ${err}")
endif()
execute_process(COMMAND "${ART}" compare "${BASELINE}" "${OUT}" ${_compare} --diff "${OUT}.diff.png" --quiet
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "differs from ${BASELINE}: ${err} ${out}")
endif()
