// MeshQuality: checks a tet mesh is a valid conforming tetrahedrisation of a box and measures
// element shape: inverted/flat tets, faces shared by other than two tets inside, minimum
// dihedral angle and the radius ratio 3 r_in / R_circ (1 for the regular tet).
#ifndef art_MeshQuality_h
#define art_MeshQuality_h

#include "AdaptiveRTReductionModule.h"

#include <string>

namespace art
{
struct QualityReport
{
  long long Tets = 0;
  long long Inverted = 0;         ///< volume <= 0 (relative to the mesh size)
  long long BoundaryFaces = 0;    ///< faces with one tet, lying on the convex hull
  long long InteriorFaces = 0;    ///< faces shared by exactly two tets
  long long OpenFaces = 0;        ///< faces with one tet not on the convex hull (a crack)
  long long OverSharedFaces = 0;  ///< faces held by three or more tets
  double MinDihedralDegrees = 0, MaxDihedralDegrees = 0;
  double MinRadiusRatio = 0, MeanRadiusRatio = 0;
  double Volume = 0; ///< sum of tet volumes (equals the box volume when conforming)

  bool Valid() const { return Inverted == 0 && OpenFaces == 0 && OverSharedFaces == 0 && Tets > 0; }
  std::string Summary() const;
};

/// `points`: x y z per vertex; `tets`: 4 ids per tet. Boundary faces are those on the points'
/// convex hull (the reducer's meshes fill a box, turned or sheared by the volume's direction).
ADAPTIVERTREDUCTION_EXPORT QualityReport MeasureQuality(const double* points, long long numPoints,
  const int* tets, long long numTets);
} // namespace art

#endif
