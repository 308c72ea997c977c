// VertexVisit: one relocation step of one vertex of a fitted lattice mesh (VertexRelocator):
// candidate places along +- the voxel gradient, +- each axis and toward its star's centroid,
// screened on a subsample of the star's voxels (ScreenRaster), the best few evaluated exactly
// (TetRaster and RelocationMoments), and the best kept when the star's squared error, with the
// vertex's value refitted (the others fixed), drops while no tet of the star flips, flattens or
// falls below the shape floor.
#ifndef art_VertexVisit_h
#define art_VertexVisit_h

#include "BisectionMesh.h"
#include "RelocationMoments.h"
#include "VertexRelocator.h"
#include "VoxelVolume.h"

#include <array>
#include <utility>
#include <vector>

namespace art
{
class VertexVisit
{
public:
  /// Per-thread working space of visits.
  struct Scratch
  {
    std::vector<double> NewMoments; ///< of the star's tets at LastQ, the last place evaluated exactly
    LatticePoint LastQ{};
    std::vector<int> Star, Sign;
    std::vector<double> QOld;
    std::vector<std::pair<double, LatticePoint>> Top;
    std::vector<std::pair<double, double>> TopValue;
    long long Count = 0;
  };

  VertexVisit(BisectionMesh& mesh, const VoxelVolume& volume, std::vector<double>& x, const RelocationOptions& options,
    RelocationMoments& moments);

  /// Visits vertex v: moves it (and updates its value and its star's moments) when that lowers
  /// its star's error; returns true when it moved. Box corners stay, vertices on a box edge or
  /// face move only within it.
  bool Visit(int v, Scratch& sc) const;

private:
  void PrepareStar(int v, const LatticePoint& p, Scratch& sc) const;
  int ScreenStride(long long voxels) const;
  std::vector<std::array<double, 3>> Directions(const LatticePoint& p, const Scratch& sc) const;
  void ScreenCandidates(int v, const LatticePoint& p, const bool fixed[3], int stride, double screenAt, Scratch& sc) const;
  void Corners(int t, int v, const LatticePoint& at, LatticePoint P[4]) const;
  double Quality(const LatticePoint P[4]) const;
  double Reach(int v, const LatticePoint& p, const double d[3], const std::vector<int>& star) const;
  void Gradient(const LatticePoint& p, double g[3]) const;
  double Sample(const double c[3]) const;
  int Others(int t, int v, double c[4]) const;
  bool Evaluate(int v, const LatticePoint& q, bool checked, Scratch& sc, double& err, double& value, int stride = 0) const;

  BisectionMesh& Mesh;
  const VoxelVolume& Vol;
  std::vector<double>& X;
  RelocationOptions Opt;
  RelocationMoments& Moments;
  int64_t Max[3];
  double Spacing[3];
  double Scale2 = 1;
};
} // namespace art

#endif
