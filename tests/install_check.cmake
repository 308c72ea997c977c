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
# The installed tool's defaults are its own copies (the demo's CT head), not the source tree's.
execute_process(COMMAND "${PREFIX}/bin/adaptivert" demo --help RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc OR NOT out MATCHES "${PREFIX}/share/adaptivert/data/ct-head-128.mha" OR NOT EXISTS "${PREFIX}/share/adaptivert/scripts/speed_accuracy_chart.py")
  message(FATAL_ERROR "installed adaptivert does not default to its installed data: ${out}${err}")
endif()
# The install carries MMG: the installed tool loads the libmmg3d beside its libraries.
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=ART_MMG_LIBRARY "${PREFIX}/bin/adaptivert" reduce
  "${SOURCE}/data/ct-head-128.mha" "${PREFIX}/check-anisotropic.vtu" --tets 600 --refinement anisotropic -q
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc OR NOT EXISTS "${PREFIX}/check-anisotropic.vtu")
  message(FATAL_ERROR "installed adaptivert cannot reduce with --refinement anisotropic: ${out}${err}")
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
# A downstream CMake project finds the installed modules with only the prefix, links them, and
# reduces the CT head (there was no AdaptiveRTConfig.cmake: find_package(AdaptiveRT) failed).
set(_down "${PREFIX}/downstream-build")
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE}/tests/downstream" -B "${_down}" -G "${GENERATOR}"
  "-DCMAKE_PREFIX_PATH=${PREFIX}" -DCMAKE_BUILD_TYPE=Release
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "a downstream project cannot find_package(AdaptiveRT) from the install: ${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${_down}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "a downstream project does not build against the install: ${out}${err}")
endif()
execute_process(COMMAND "${_down}/downstream" "${SOURCE}/data/ct-head-128.mha"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc OR NOT out MATCHES "reduced to [0-9]+ tets")
  message(FATAL_ERROR "the downstream program failed: ${out}${err}")
endif()
message(STATUS "installed tool and Python package work; a downstream project ${out}")
