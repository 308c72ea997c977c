#include "ReducedLevel.h"

#include "MeanSpacing.h"

#include <algorithm>
#include <utility>

namespace art
{
std::vector<double> OutputValues(const BisectionMesh& mesh, const LeastSquaresFit& fit, std::vector<double> x,
  bool clamp, const OpacityImportance* cap)
{
  if (clamp || cap)
  {
    std::vector<double> lo, hi;
    fit.VertexVoxelRange(mesh, lo, hi);
    for (std::size_t v = 0; v < lo.size(); ++v)
    {
      // A vertex over no voxel centre (lo > hi) keeps its fitted value.
      const bool over = lo[v] <= hi[v] && (clamp || cap->Opacity(x[v]) > cap->MaxOpacity(lo[v], hi[v]));
      x[v] = over ? std::min(hi[v], std::max(lo[v], x[v])) : x[v];
    }
  }
  return x;
}

void WritePositiveTet(std::array<int, 4> v, const std::vector<double>& points, int* out)
{
  const double* p[4];
  for (int a = 0; a < 4; ++a)
  {
    p[a] = &points[3 * static_cast<size_t>(v[a])];
  }
  double e[3][3];
  for (int a = 0; a < 3; ++a)
  {
    for (int d = 0; d < 3; ++d)
    {
      e[a][d] = p[a + 1][d] - p[0][d];
    }
  }
  const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
    e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  if (det < 0)
  {
    std::swap(v[1], v[2]);
  }
  std::copy(v.begin(), v.end(), out);
}

ReducedMesh Snapshot(const VoxelVolume& vol, const BisectionMesh& mesh, const std::vector<double>& x,
  VoxelErrorReport e)
{
  ReducedMesh out;
  out.TetRms = std::move(e.TetRms);
  out.TetMax = std::move(e.TetMax);
  out.Rms = e.Rms;
  out.Max = e.Max;
  out.WeightedRms = e.WeightedRms;
  out.WeightedMax = e.WeightedMax;
  const int nv = mesh.NumberOfVertices(), nt = mesh.NumberOfTets();
  out.Points.resize(3 * static_cast<size_t>(nv));
  const double S = static_cast<double>(BisectionMesh::Scale);
  for (int v = 0; v < nv; ++v)
  {
    const LatticePoint& p = mesh.Vertex(v);
    const double ijk[3] = { p.x / S, p.y / S, p.z / S };
    vol.IndexToWorld(ijk, &out.Points[3 * static_cast<size_t>(v)]);
  }
  out.Values.assign(x.begin(), x.begin() + nv);
  out.Tets.resize(4 * static_cast<size_t>(nt));
  for (int t = 0; t < nt; ++t)
  {
    WritePositiveTet(mesh.Tet(t), out.Points, &out.Tets[4 * static_cast<size_t>(t)]);
  }
  out.Range[0] = vol.Range[0];
  out.Range[1] = vol.Range[1];
  out.SourceSpacing = MeanVoxelSpacing(vol.Dims, vol.Spacing); // a preset's unit distance follows it
  out.Source = vol.Statistics;
  out.ScalarName = vol.Name;
  return out;
}
} // namespace art
