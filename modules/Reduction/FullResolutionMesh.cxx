#include "FullResolutionMesh.h"

#include "AvailableMemory.h"
#include "Error.h"
#include "MeanSpacing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace art
{
long long FullResolutionTetCount(const VoxelVolume& v)
{
  return 5LL * std::max(v.Dims[0] - 1, 0) * std::max(v.Dims[1] - 1, 0) * std::max(v.Dims[2] - 1, 0);
}

ReducedMesh FullResolutionMesh(const VoxelVolume& v)
{
  const auto start = std::chrono::steady_clock::now();
  const int* d = v.Dims;
  if (d[0] < 2 || d[1] < 2 || d[2] < 2)
  {
    throw Error("a volume of " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " + std::to_string(d[2]) +
        " voxels has no cells to make tets of",
      v.File);
  }
  const long long np = v.NumberOfVoxels(), nt = FullResolutionTetCount(v);
  // Points, values, tets, two per-tet errors: what the mesh holds, and its VTK copy again.
  const double bytes = 2.0 * (np * 32.0 + nt * 32.0);
  const double avail = AvailableMemoryBytes();
  if (avail > 0 && bytes > 0.9 * avail)
  {
    throw Error("its full-resolution mesh (" + std::to_string(nt) + " tets) needs about " +
        std::to_string(static_cast<long long>(std::ceil(bytes / 1e9))) + " GB, more than the memory available; "
        "give a smaller --tets",
      v.File);
  }
  ReducedMesh m;
  m.Points.resize(3 * static_cast<std::size_t>(np));
  m.Values.resize(static_cast<std::size_t>(np));
  for (int k = 0, id = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i, ++id)
      {
        const double ijk[3] = { double(i), double(j), double(k) };
        v.IndexToWorld(ijk, &m.Points[3 * static_cast<std::size_t>(id)]);
        m.Values[static_cast<std::size_t>(id)] = v.Value(id);
      }
  static const int five[5][4] = { { 0, 1, 2, 4 }, { 3, 1, 2, 7 }, { 5, 1, 4, 7 }, { 6, 2, 4, 7 }, { 1, 2, 4, 7 } };
  m.Tets.reserve(4 * static_cast<std::size_t>(nt));
  const auto orient = [&](const int* t) {
    const double* a = &m.Points[3 * t[0]];
    double e[3][3];
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        e[r][c] = m.Points[3 * t[r + 1] + c] - a[c];
      }
    }
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
      e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  };
  for (int k = 0; k + 1 < d[2]; ++k)
    for (int j = 0; j + 1 < d[1]; ++j)
      for (int i = 0; i + 1 < d[0]; ++i)
      {
        int c[8];
        for (int b = 0; b < 8; ++b)
        {
          c[b] = ((k + ((b >> 2) & 1)) * d[1] + j + ((b >> 1) & 1)) * d[0] + i + (b & 1);
        }
        const int flip = (i + j + k) & 1; // mirror odd cells in x so shared face diagonals agree
        for (const auto& f : five)
        {
          int t[4] = { c[f[0] ^ flip], c[f[1] ^ flip], c[f[2] ^ flip], c[f[3] ^ flip] };
          if (orient(t) < 0) // mirrored cells, and a direction matrix that mirrors
          {
            std::swap(t[2], t[3]);
          }
          m.Tets.insert(m.Tets.end(), t, t + 4);
        }
      }
  m.TetRms.assign(static_cast<std::size_t>(nt), 0.0);
  m.TetMax.assign(static_cast<std::size_t>(nt), 0.0);
  m.Range[0] = v.Range[0];
  m.Range[1] = v.Range[1];
  m.SourceSpacing = MeanVoxelSpacing(v.Dims, v.Spacing); // as TetReducer records it
  m.Source = v.Statistics;
  m.TargetTets = nt;
  m.ScalarName = v.Name;
  // The summary's "time": a 42M-tet mesh takes seconds to lay out (it said 0.00 s).
  m.BuildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m;
}
} // namespace art
