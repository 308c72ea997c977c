# render --save-mesh keeps the mesh it rendered: rendering that .vtu again draws the same image
# (the same tets, values and transfer function), and it is a tet mesh any VTK reader opens.
file(MAKE_DIRECTORY "${OUT}")
set(_view --size 48x48 --azimuth 30 --no-error -q)
execute_process(COMMAND "${ART}" render "${DATA}" --tets 2000 --save-mesh "${OUT}/kept.vtu" -o "${OUT}/volume.png" ${_view}
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(rc OR NOT EXISTS "${OUT}/kept.vtu")
  message(FATAL_ERROR "render --save-mesh failed or wrote nothing: ${err}")
endif()
execute_process(COMMAND "${ART}" render "${OUT}/kept.vtu" -o "${OUT}/mesh.png" ${_view}
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "the saved mesh does not render: ${err}")
endif()
execute_process(COMMAND "${ART}" compare --min-psnr 60 "${OUT}/volume.png" "${OUT}/mesh.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "the saved mesh draws another image: ${out}${err}")
endif()
execute_process(COMMAND "${ART}" info "${OUT}/kept.vtu" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(rc OR NOT out MATCHES "vtkTetra +(1,9[0-9][0-9]|2,[01][0-9][0-9])")
  message(FATAL_ERROR "the saved mesh is not the 2000-tet reduction (within 5%): ${out}")
endif()
