// MmgRemesher: anisotropic remeshing of a tet mesh of a box to a tensor metric with MMG3D
// (Dapogny, Dobrzynski & Frey, "Three-dimensional adaptive domain remeshing, implicit domain
// meshing, and applications to free and moving boundary problems", JCP 262, 2014), through
// libmmg3d's C API. The library is loaded when first needed, so every other refinement works
// without it and a missing or broken MMG is an art::Error, not a failure to start.
#ifndef art_MmgRemesher_h
#define art_MmgRemesher_h

#include "AdaptiveRTReductionModule.h"

#include <string>
#include <vector>

namespace art
{
struct RemeshOptions
{
  double Hmin = 0.5;    ///< shortest edge MMG may make, in the points' units
  double Hmax = 64;     ///< longest edge
  double Hgrad = -1;    ///< size gradation (< 0: none; the metric is taken as given)
  double Hausd = 1e3;   ///< boundary approximation (the boundary is the box's planes)
  int Verbose = -1;     ///< MMG's verbosity (-1: silent)
  bool NoMove = false;  ///< MMG leaves vertices where it puts them (faster, flatter tets)
  double ExpectedVertices = 0; ///< about how many the output has (sizes MMG's arrays; 0: the input's)
};

/// A tet mesh and, per vertex, a symmetric metric tensor (m11 m12 m13 m22 m23 m33): edges of
/// unit length in the metric are what MMG makes.
struct MetricMesh
{
  std::vector<double> Points; ///< x y z per vertex
  std::vector<int> Tets;      ///< 4 vertex ids per tet
  std::vector<double> Metric; ///< 6 per vertex
};

class ADAPTIVERTREDUCTION_EXPORT MmgRemesher
{
public:
  /// True when libmmg3d can be loaded; otherwise `why` (when given) says what failed.
  static bool Available(std::string* why = nullptr);
  /// The file libmmg3d was (or would be) loaded from: $ART_MMG_LIBRARY when set, else
  /// libmmg3d.so.5 beside this module's library when it is there, else the system's.
  static std::string LibraryPath();

  /// Remeshes `in` (a conforming mesh of an axis-aligned box) to its metric. The box's faces
  /// stay the boundary (its edges as ridges, its corners kept); the output is MMG's mesh with its
  /// boundary points put back on the box's planes exactly. Throws art::Error when MMG cannot be
  /// loaded or fails. MMG runs on the calling thread, one call at a time in the process (it keeps
  /// global state); the process's signal handlers, which MMG replaces, are restored after it.
  static void Remesh(const MetricMesh& in, const double boxLo[3], const double boxHi[3], const RemeshOptions& options,
    std::vector<double>& points, std::vector<int>& tets);
};
} // namespace art

#endif
