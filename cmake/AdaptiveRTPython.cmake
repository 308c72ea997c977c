# Python wrapping of every AdaptiveRT module into the package `adaptivert`.
# __init__.py imports each wrapped module, so `adaptivert.vtkTetRayCastMapper` etc. resolve.
set(ART_PYTHON_DESTINATION "${CMAKE_INSTALL_LIBDIR}/python3/dist-packages")
set(ART_PYTHONPATH "${CMAKE_BINARY_DIR}/${ART_PYTHON_DESTINATION}")

vtk_module_wrap_python(
  MODULES             ${art_modules}
  TARGET              AdaptiveRT::Python
  WRAPPED_MODULES     art_wrapped_modules
  PYTHON_PACKAGE      adaptivert
  MODULE_DESTINATION  "${ART_PYTHON_DESTINATION}"
  CMAKE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}/cmake/adaptivert"
  LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  INSTALL_EXPORT      AdaptiveRTPython
  SOABI               "${Python3_SOABI}"
  BUILD_STATIC        OFF)

set(_art_imports "")
foreach(_m IN LISTS art_wrapped_modules)
  get_property(_lib TARGET "${_m}" PROPERTY "INTERFACE_vtk_module_library_name")
  string(APPEND _art_imports "from .${_lib} import *  # noqa: F401,F403\n")
endforeach()
set(_init "${ART_PYTHONPATH}/adaptivert/__init__.py")
file(GENERATE OUTPUT "${_init}" CONTENT
"\"\"\"AdaptiveRT: adaptive tetrahedral reduction and ray casting around VTK.\"\"\"
# VTK's own Python modules must be loaded before ours resolve their base classes.
import vtkmodules.vtkCommonCore  # noqa: F401
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
${_art_imports}
__version__ = \"${PROJECT_VERSION}\"
")
install(FILES "${_init}" DESTINATION "${ART_PYTHON_DESTINATION}/adaptivert")
