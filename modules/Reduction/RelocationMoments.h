// RelocationMoments: the voxel moments of each tet of a lattice mesh (count, sum w f^2, sum w f l_a,
// sum w l_a l_b) from which the squared error of a vertex's star, for any values at its corners,
// follows without a voxel pass (VertexRelocator). With a transfer function each voxel's weight w
// is frozen at the fit the relocation starts from, as one reweighting step of the fit.
#ifndef art_RelocationMoments_h
#define art_RelocationMoments_h

#include "BisectionMesh.h"
#include "VoxelVolume.h"

#include <vector>

namespace art
{
class OpacityImportance;
class Progress;

class RelocationMoments
{
public:
  /// Doubles per tet: count, sum w f^2, sum w f l_a (4), sum w l_a l_b for a <= b (10, in the
  /// order 00 01 02 03 11 12 13 22 23 33).
  static constexpr int NM = 16;
  /// Where sum w l_a l_b sits in a tet's moments.
  static int Pair(int a, int b);

  RelocationMoments(const VoxelVolume& volume, const OpacityImportance* importance);

  /// The weights at the fit `x` (with an importance), then every tet's moments; `progress`
  /// (optional) advances by `units` for each voxel pass and may cancel (art::Error "cancelled").
  void Compute(const BisectionMesh& mesh, const std::vector<double>& x, Progress* progress, double units);
  /// The moments of a tet with corners P into m (NM doubles); false (and zeros) for a flat tet.
  bool OfTet(const LatticePoint P[4], double* m) const;
  double* Of(int t) { return &Moments[static_cast<size_t>(t) * NM]; }
  const double* Of(int t) const { return &Moments[static_cast<size_t>(t) * NM]; }
  /// Adds tet moments m's squared-error terms with its corner vi unknown and the others at c:
  /// the error is srr - 2 u srp + u^2 spp for the value u at vi.
  static void AddStarTerms(const double* m, const double c[4], int vi, double& srr, double& srp, double& spp,
    long long& count);
  /// Each voxel's frozen weight (empty without an importance).
  const std::vector<float>& Weights() const { return W; }

private:
  const VoxelVolume& Vol;
  const OpacityImportance* Imp;
  std::vector<double> Moments; ///< NM per tet, for the tets' current places
  std::vector<float> W;
};
} // namespace art

#endif
