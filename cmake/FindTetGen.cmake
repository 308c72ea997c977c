# FindTetGen: TetGen 1.5 as Debian's libtet1.5-dev ships it (tetgen.h and libtet.so, built with
# TETLIBRARY). Sets TetGen_FOUND, TetGen_INCLUDE_DIR and TetGen_LIBRARY.
find_path(TetGen_INCLUDE_DIR tetgen.h)
find_library(TetGen_LIBRARY NAMES tet tetgen)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(TetGen REQUIRED_VARS TetGen_LIBRARY TetGen_INCLUDE_DIR)
mark_as_advanced(TetGen_INCLUDE_DIR TetGen_LIBRARY)
if(TetGen_FOUND AND NOT TARGET TetGen::TetGen)
  add_library(TetGen::TetGen UNKNOWN IMPORTED)
  set_target_properties(TetGen::TetGen PROPERTIES
    IMPORTED_LOCATION "${TetGen_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${TetGen_INCLUDE_DIR}"
    INTERFACE_COMPILE_DEFINITIONS TETLIBRARY)
endif()
