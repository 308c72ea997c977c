// Shared by the Reduction tests: analytic fields as images, and the validity checks every
// reduced or refined mesh must pass (orientation, conformity, a face shared by at most two tets).
#ifndef art_ReductionFixtures_h
#define art_ReductionFixtures_h

#include "BisectionMesh.h"
#include "MeshQuality.h"
#include "ParallelTiles.h"
#include "TetReducer.h"
#include "VoxelRaster.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkShortArray.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <functional>
#include <utility>
#include <vector>

namespace fixtures
{
/// An image of f sampled at its points, as a "density" array of doubles (or shorts).
inline vtkSmartPointer<vtkImageData> Field(const int d[3], const double spacing[3], const double origin[3],
  const std::function<double(double, double, double)>& f, bool shortValues = false)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(d[0], d[1], d[2]);
  img->SetSpacing(spacing[0], spacing[1], spacing[2]);
  img->SetOrigin(origin[0], origin[1], origin[2]);
  vtkSmartPointer<vtkDataArray> a;
  if (shortValues)
  {
    a = vtkSmartPointer<vtkShortArray>::New();
  }
  else
  {
    a = vtkSmartPointer<vtkDoubleArray>::New();
  }
  a->SetName("density");
  a->SetNumberOfTuples(img->GetNumberOfPoints());
  for (vtkIdType i = 0; i < img->GetNumberOfPoints(); ++i)
  {
    double p[3];
    img->GetPoint(i, p);
    a->SetTuple1(i, f(p[0], p[1], p[2]));
  }
  img->GetPointData()->SetScalars(a);
  return img;
}

/// A reduced mesh: positively oriented, conforming, each face in one or two tets.
inline void ExpectValid(const art::ReducedMesh& m)
{
  const auto q = art::MeasureQuality(m.Points.data(), m.NumberOfVertices(), m.Tets.data(), m.NumberOfTets());
  EXPECT_TRUE(q.Valid()) << q.Summary();
  EXPECT_EQ(q.Inverted, 0);
  EXPECT_EQ(q.OpenFaces, 0);
  EXPECT_EQ(q.OverSharedFaces, 0);
  EXPECT_EQ(q.InteriorFaces * 2 + q.BoundaryFaces, 4 * m.NumberOfTets());
}

/// Runs opt on v with 1 and with 2 threads: the same tets, points, fit and error; returns the mesh.
inline art::ReducedMesh ExpectSameForOneAndTwoThreads(const art::ReducerOptions& opt, const art::VoxelVolume& v)
{
  const int before = art::GetThreadCount();
  art::SetThreadCount(1);
  const auto a = art::TetReducer(opt).Run(v);
  art::SetThreadCount(2);
  const auto b = art::TetReducer(opt).Run(v);
  art::SetThreadCount(before);
  EXPECT_EQ(a.back().Tets, b.back().Tets);
  EXPECT_EQ(a.back().Points, b.back().Points);
  EXPECT_EQ(a.back().Values, b.back().Values);
  EXPECT_EQ(a.back().Rms, b.back().Rms);
  return a.back();
}

/// Six times the signed volume of tet t, in lattice units.
inline double SignedVolume6(const art::BisectionMesh& m, int t)
{
  const auto v = m.Tet(t);
  const auto &a = m.Vertex(v[0]), &b = m.Vertex(v[1]), &c = m.Vertex(v[2]), &d = m.Vertex(v[3]);
  const double e[3][3] = { { double(b.x - a.x), double(b.y - a.y), double(b.z - a.z) },
    { double(c.x - a.x), double(c.y - a.y), double(c.z - a.z) },
    { double(d.x - a.x), double(d.y - a.y), double(d.z - a.z) } };
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
    e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

/// MeasureQuality of a bisection mesh (its tets turned positive: bisection order has either sign);
/// no tet may be flat.
inline art::QualityReport Check(const art::BisectionMesh& m)
{
  std::vector<double> p;
  for (int v = 0; v < m.NumberOfVertices(); ++v)
  {
    const auto& q = m.Vertex(v);
    p.insert(p.end(), { double(q.x), double(q.y), double(q.z) });
  }
  std::vector<int> t;
  for (int i = 0; i < m.NumberOfTets(); ++i)
  {
    auto v = m.Tet(i);
    const double det = SignedVolume6(m, i);
    EXPECT_NE(det, 0.0);
    if (det < 0)
    {
      std::swap(v[1], v[2]);
    }
    t.insert(t.end(), v.begin(), v.end());
  }
  return art::MeasureQuality(p.data(), m.NumberOfVertices(), t.data(), m.NumberOfTets());
}
/// The lattice raster gives every voxel of dims to exactly one tet, with barycentric weights
/// that sum to 1 and are not negative.
inline void ExpectEachVoxelOwnedOnce(const art::BisectionMesh& m, const int dims[3])
{
  std::vector<int> owner(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2], 0);
  for (int t = 0; t < m.NumberOfTets(); ++t)
  {
    art::LatticePoint P[4];
    for (int a = 0; a < 4; ++a)
    {
      P[a] = m.Vertex(m.Tet(t)[a]);
    }
    art::TetRaster r;
    ASSERT_TRUE(r.Setup(P));
    r.ForEachVoxel(dims, [&](long long idx, const double* l) {
      ++owner[idx];
      EXPECT_NEAR(l[0] + l[1] + l[2] + l[3], 1.0, 1e-12);
      for (int a = 0; a < 4; ++a)
      {
        EXPECT_GE(l[a], -1e-12);
      }
    });
  }
  for (std::size_t i = 0; i < owner.size(); ++i)
  {
    ASSERT_EQ(owner[i], 1) << "voxel " << i;
  }
}
} // namespace fixtures

#endif
