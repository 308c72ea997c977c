# Installs the build into a fresh prefix and checks that the installed tool runs and that
# `import adaptivert` works from the installed package, with no help from the build tree.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${PREFIX}"
  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "install failed: ${err}")
endif()
execute_process(COMMAND "${PREFIX}/bin/adaptivert" --version RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc OR NOT out MATCHES "^adaptivert [0-9]")
  message(FATAL_ERROR "installed adaptivert does not run: ${out}${err}")
endif()
# An EXR goes through the OpenImageIO plug-in, which the installed libraries must find beside them.
execute_process(COMMAND "${PREFIX}/bin/adaptivert" render "${SOURCE}/data/ct-head-128.mha" -o "${PREFIX}/check.exr"
  --size 8x8 --tets 500 --no-error -q RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc OR NOT EXISTS "${PREFIX}/check.exr")
  message(FATAL_ERROR "installed adaptivert cannot write an EXR: ${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env "PYTHONPATH=${PREFIX}/${PYDIR}"
  "${PYTHON}" -c "import adaptivert, os; assert adaptivert.__file__.startswith('${PREFIX}'), adaptivert.__file__; m = adaptivert.vtkImageMetrics(); assert m.CompareFiles('${PREFIX}/check.exr', '${PREFIX}/check.exr'), m.GetErrorMessage(); print(m.GetClassName())"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY "${PREFIX}")
if(rc OR NOT out MATCHES "vtkImageMetrics")
  message(FATAL_ERROR "import adaptivert from the install failed: ${out}${err}")
endif()
message(STATUS "installed tool and Python package work")
