#include "ReductionBaselines.h"

#include "Error.h"
#include "ParallelTiles.h"

#include <vtkDataArray.h>
#include <vtkDataSetTriangleFilter.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkProbeFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridQuadricDecimation.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace art
{
vtkSmartPointer<vtkUnstructuredGrid> TetrahedralizeVolume(vtkImageData* image)
{
  auto tri = vtkSmartPointer<vtkDataSetTriangleFilter>::New();
  tri->SetInputData(image);
  tri->TetrahedraOnlyOn();
  tri->Update();
  vtkSmartPointer<vtkUnstructuredGrid> out = tri->GetOutput();
  return out;
}

vtkSmartPointer<vtkUnstructuredGrid> QuadricDecimate(vtkUnstructuredGrid* grid, long long tets, const char* scalars)
{
  // Its randomized collapses stall above the target on big inputs: run it again on its own
  // output while that still helps (at most 8 passes).
  vtkSmartPointer<vtkUnstructuredGrid> out = grid;
  for (int pass = 0; pass < 8 && out->GetNumberOfCells() > tets * 21 / 20; ++pass)
  {
    const vtkIdType before = out->GetNumberOfCells();
    auto dec = vtkSmartPointer<vtkUnstructuredGridQuadricDecimation>::New();
    dec->SetInputData(out);
    dec->SetNumberOfTetsOutput(static_cast<int>(tets));
    dec->SetScalarsName(scalars);
    dec->Update();
    vtkSmartPointer<vtkUnstructuredGrid> next = dec->GetOutput();
    if (next->GetNumberOfCells() == 0)
    {
      throw Error(std::string("quadric decimation failed (no scalars named '") + scalars + "'?)");
    }
    // It writes its field as "scalars": give it back the input's name.
    if (vtkDataArray* a = next->GetPointData()->GetScalars())
    {
      a->SetName(scalars);
    }
    out = next;
    if (out->GetNumberOfCells() >= before * 99 / 100)
    {
      break;
    }
  }
  return out;
}

BaselineError ProbeError(vtkImageData* image, vtkUnstructuredGrid* grid, const char* scalars,
  std::vector<char>* coveredOut, const std::vector<char>* only)
{
  auto probe = vtkSmartPointer<vtkProbeFilter>::New();
  probe->SetInputData(image);
  probe->SetSourceData(grid);
  probe->Update();
  vtkDataSet* out = probe->GetOutput();
  vtkDataArray* fit = out->GetPointData()->GetArray(scalars);
  vtkDataArray* valid = out->GetPointData()->GetArray(probe->GetValidPointMaskArrayName());
  vtkDataArray* orig = image->GetPointData()->GetScalars();
  if (!fit || !valid || !orig)
  {
    throw Error(std::string("probing found no array '") + scalars + "'");
  }
  BaselineError e;
  double sse = 0, covered = 0;
  long long counted = 0;
  const vtkIdType n = image->GetNumberOfPoints();
  if (coveredOut)
  {
    coveredOut->assign(static_cast<std::size_t>(n), 0);
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool ok = valid->GetTuple1(i) != 0;
    const double d = orig->GetTuple1(i) - (ok ? fit->GetTuple1(i) : 0.0);
    e.Uncovered += ok ? 0 : 1;
    covered += ok ? d * d : 0.0;
    if (coveredOut)
    {
      (*coveredOut)[i] = ok ? 1 : 0;
    }
    if (only && !(*only)[i])
    {
      continue;
    }
    ++counted;
    sse += d * d;
    e.Max = std::max(e.Max, std::fabs(d));
  }
  e.Rms = counted > 0 ? std::sqrt(sse / static_cast<double>(counted)) : 0.0;
  e.CoveredRms = n > e.Uncovered ? std::sqrt(covered / static_cast<double>(n - e.Uncovered)) : 0.0;
  e.Vertices = grid->GetNumberOfPoints();
  e.Tets = grid->GetNumberOfCells();
  return e;
}

BaselineError UniformDownsampleError(const VoxelVolume& v, long long vertices)
{
  const int* d = v.Dims;
  double L[3];
  for (int a = 0; a < 3; ++a)
  {
    L[a] = (d[a] - 1) * std::fabs(v.Spacing[a]);
  }
  // n_a nodes per axis with n0 n1 n2 ~ vertices and node spacing about equal in world units.
  // Scan the node spacing for the node count closest to `vertices`.
  int n[3] = { 2, 2, 2 };
  long long best = -1;
  for (double h = std::cbrt(L[0] * L[1] * L[2] / std::max(1.0, double(vertices))) * 0.5;
       h < std::max(L[0], std::max(L[1], L[2])) * 2; h *= 1.01)
  {
    int m[3];
    for (int a = 0; a < 3; ++a)
    {
      m[a] = std::max(2, std::min(d[a], static_cast<int>(std::lround(L[a] / h)) + 1));
    }
    const long long c = static_cast<long long>(m[0]) * m[1] * m[2];
    if (best < 0 || std::llabs(c - vertices) < std::llabs(best - vertices))
    {
      best = c;
      std::copy(m, m + 3, n);
    }
  }
  auto voxel = [&](long long i, long long j, long long k) { return v.Value(i + d[0] * (j + d[1] * k)); };
  auto trilinear = [](auto&& at, const int* dims, double x, double y, double z) {
    const int i = std::min(dims[0] - 2, static_cast<int>(x)), j = std::min(dims[1] - 2, static_cast<int>(y)),
              k = std::min(dims[2] - 2, static_cast<int>(z));
    const double fx = x - i, fy = y - j, fz = z - k;
    double s = 0;
    for (int c = 0; c < 8; ++c)
    {
      const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
      s += (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy) * (dz ? fz : 1 - fz) * at(i + dx, j + dy, k + dz);
    }
    return s;
  };
  // Node (p,q,r) sits at voxel coordinate p (d-1)/(n-1) along each axis.
  double step[3];
  for (int a = 0; a < 3; ++a)
  {
    step[a] = double(d[a] - 1) / (n[a] - 1);
  }
  std::vector<double> coarse(static_cast<size_t>(n[0]) * n[1] * n[2]);
  for (int r = 0; r < n[2]; ++r)
    for (int q = 0; q < n[1]; ++q)
      for (int p = 0; p < n[0]; ++p)
      {
        coarse[p + n[0] * (q + static_cast<size_t>(n[1]) * r)] =
          trilinear(voxel, d, p * step[0], q * step[1], r * step[2]);
      }
  auto node = [&](long long p, long long q, long long r) { return coarse[p + n[0] * (q + n[1] * r)]; };
  std::vector<double> sse(static_cast<size_t>(d[2])), mx(static_cast<size_t>(d[2]));
  ForEachRange(d[2], 1, [&](long long k0, long long k1, Counters&) {
    for (long long k = k0; k < k1; ++k)
    {
      double s = 0, m = 0;
      for (int j = 0; j < d[1]; ++j)
        for (int i = 0; i < d[0]; ++i)
        {
          const double e = voxel(i, j, k) - trilinear(node, n, i / step[0], j / step[1], k / step[2]);
          s += e * e;
          m = std::max(m, std::fabs(e));
        }
      sse[k] = s;
      mx[k] = m;
    }
  });
  BaselineError e;
  double total = 0;
  for (int k = 0; k < d[2]; ++k)
  {
    total += sse[k];
    e.Max = std::max(e.Max, mx[k]);
  }
  e.Rms = std::sqrt(total / static_cast<double>(v.NumberOfVoxels()));
  e.Vertices = static_cast<long long>(n[0]) * n[1] * n[2];
  e.Tets = 6LL * (n[0] - 1) * (n[1] - 1) * (n[2] - 1);
  return e;
}
} // namespace art
