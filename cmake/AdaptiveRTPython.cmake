# Python wrapping of every AdaptiveRT module into the package `adaptivert`. Included before the
# modules are built (their Python tests need ART_PYTHONPATH); art_wrap_python() runs after.
# __init__.py imports each wrapped module, so `adaptivert.vtkTetRayCastMapper` etc. resolve.
vtk_module_python_default_destination(ART_PYTHON_DESTINATION)
set(ART_PYTHONPATH "${CMAKE_BINARY_DIR}/${ART_PYTHON_DESTINATION}")

function(art_wrap_python modules_var)
  vtk_module_wrap_python(
    MODULES             ${${modules_var}}
    TARGET              AdaptiveRT::Python
    WRAPPED_MODULES     _wrapped
    PYTHON_PACKAGE      adaptivert
    MODULE_DESTINATION  "${ART_PYTHON_DESTINATION}"
    CMAKE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}/cmake/adaptivert"
    LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    INSTALL_EXPORT      AdaptiveRTPython
    SOABI               "${Python3_SOABI}"
    BUILD_STATIC        OFF)

  set(_imports "")
  foreach(_m IN LISTS _wrapped)
    get_property(_lib TARGET "${_m}" PROPERTY "INTERFACE_vtk_module_library_name")
    string(APPEND _imports "from .${_lib} import *  # noqa: F401,F403\n")
  endforeach()
  set(_init "${ART_PYTHONPATH}/adaptivert/__init__.py")
  file(GENERATE OUTPUT "${_init}" CONTENT
"\"\"\"AdaptiveRT: adaptive tetrahedral reduction and ray casting around VTK.\"\"\"
# VTK's own Python modules must be loaded before ours resolve their base classes.
import vtkmodules.vtkCommonCore  # noqa: F401
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
${_imports}
__version__ = \"${PROJECT_VERSION}\"
")
  install(FILES "${_init}" DESTINATION "${ART_PYTHON_DESTINATION}/adaptivert")
endfunction()
