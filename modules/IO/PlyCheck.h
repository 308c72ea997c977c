// PlyCheck: reads a PLY header and checks it is complete, then reads the body through and checks
// that every element is there and every face names an existing vertex, before vtkPLYReader sees
// the file (which reads past the end of a truncated file and segfaults on a bad face index).
#ifndef art_PlyCheck_h
#define art_PlyCheck_h

#include "AdaptiveRTIOModule.h"

#include <string>
#include <vector>

namespace art
{
/// Throws art::Error naming `path` when the file is not a well-formed PLY. When the vertices'
/// x, y and z are doubles and `xyz` is given, it receives them (x y z per vertex; else it is left
/// empty): vtkPLYReader keeps only floats. Likewise `rgb` receives floating-point red, green and
/// blue as written (vtkPLYReader casts them to 8 bits: 1.0 became 1 of 255).
ADAPTIVERTIO_EXPORT void CheckPly(
  const std::string& path, std::vector<double>* xyz = nullptr, std::vector<double>* rgb = nullptr);
} // namespace art

#endif
