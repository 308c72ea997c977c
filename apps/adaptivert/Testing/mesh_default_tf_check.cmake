# A mesh reduced from a volume renders by default as the volume does: `reduce` records the
# volume's background, window and labels in the mesh, and `render` of the .vtu chooses the same
# transfer function and frame as `render --tets` of the volume. Thresholds: the mesh `render
# --save-mesh` kept draws the identical image (RMSE 0); the mesh `reduce --tf auto` made (another
# reduction of the same budget) >= 25 dB over the object's pixels (27.3 dB measured; a grey ramp
# over the mesh's own overshooting values, the old default, filled the box with fog).
foreach(_v ART DATA OUT)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "mesh_default_tf_check.cmake needs -D${_v}=")
  endif()
endforeach()
file(MAKE_DIRECTORY "${OUT}")
set(_view --size 96x96 --azimuth 30 -q --no-error)
# reduce --tf auto weights the fit as render --tets does (by what the default function shows).
execute_process(COMMAND "${ART}" reduce "${DATA}" "${OUT}/mesh.vtu" --tets 20000 --tf auto -q
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "reduce failed: ${err}")
endif()
execute_process(COMMAND "${ART}" render "${OUT}/mesh.vtu" -o "${OUT}/mesh.png" ${_view}
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "render of the mesh failed: ${err}")
endif()
execute_process(COMMAND "${ART}" render "${DATA}" --tets 20000 -o "${OUT}/volume.png" ${_view}
  --save-mesh "${OUT}/kept.vtu" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "render of the volume failed: ${err}")
endif()
execute_process(COMMAND "${ART}" render "${OUT}/kept.vtu" -o "${OUT}/kept.png" ${_view}
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
execute_process(COMMAND "${ART}" compare --json "${OUT}/volume.png" "${OUT}/kept.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE kept ERROR_VARIABLE err)
string(JSON _kept GET "${kept}" rmse) # identical images: rmse 0 (psnr_db is null, infinite)
if(rc OR NOT _kept STREQUAL "0")
  message(FATAL_ERROR "the kept mesh draws RMSE ${_kept} from the volume's own render of it (${err})")
endif()
execute_process(COMMAND "${ART}" compare --json "${OUT}/volume.png" "${OUT}/mesh.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE compared ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "compare failed: ${err}")
endif()
string(JSON _psnr GET "${compared}" psnr_db)
string(JSON _object GET "${compared}" object_psnr_db)
string(REGEX MATCH "^[0-9]+" _whole "${_object}")
if(NOT _psnr STREQUAL "" AND (_whole STREQUAL "" OR _whole LESS 25))
  message(FATAL_ERROR "the mesh's default render is ${_object} dB (object pixels) from the volume's")
endif()
message(STATUS "mesh vs volume: ${_psnr} dB whole frame, ${_object} dB object")
