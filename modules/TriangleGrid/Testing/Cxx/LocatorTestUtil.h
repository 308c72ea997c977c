// Shared helpers for the locator query tests: query points (inside, near and far from a surface),
// VTK's own cell distance, generated surfaces (a strip sphere, a plane of quads).
#ifndef art_LocatorTestUtil_h
#define art_LocatorTestUtil_h

#include "DataLoader.h"
#include "vtkTriangleGridLocator.h"

#include <vtkAlgorithm.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkStripper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace arttest
{
const int Kinds[] = { vtkTriangleGridLocator::BRUTE_FORCE, vtkTriangleGridLocator::UNIFORM_GRID,
  vtkTriangleGridLocator::RECURSIVE_GRID, vtkTriangleGridLocator::OCTREE };

inline double Diagonal(vtkPolyData* pd)
{
  double b[6];
  pd->GetBounds(b);
  return std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
}

// Query points: a third uniform in the (slightly grown) bounding box, a third near the surface
// (a random point of a random cell moved up to 1% of the diagonal), a third 1-10 diagonals away.
inline std::vector<std::array<double, 3>> QueryPoints(vtkPolyData* pd, size_t n, unsigned seed)
{
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  double b[6];
  pd->GetBounds(b);
  const double diag = Diagonal(pd);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  std::vector<std::array<double, 3>> xs(n);
  vtkNew<vtkIdList> ids;
  for (size_t i = 0; i < n; ++i)
  {
    std::array<double, 3>& x = xs[i];
    std::normal_distribution<double> nd;
    double d[3] = { nd(g), nd(g), nd(g) };
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + 1e-300;
    if (i % 3 == 0)
    {
      for (int a = 0; a < 3; ++a)
      {
        const double pad = 0.05 * (b[2 * a + 1] - b[2 * a]);
        x[a] = b[2 * a] - pad + u(g) * (b[2 * a + 1] - b[2 * a] + 2 * pad);
      }
    }
    else if (i % 3 == 1)
    {
      const vtkIdType cell = static_cast<vtkIdType>(u(g) * pd->GetNumberOfCells()) % pd->GetNumberOfCells();
      pd->GetCellPoints(cell, ids);
      double w[3] = { u(g), u(g), 0 };
      if (w[0] + w[1] > 1)
      {
        w[0] = 1 - w[0], w[1] = 1 - w[1];
      }
      w[2] = 1 - w[0] - w[1];
      x = { 0, 0, 0 };
      for (int k = 0; k < 3; ++k)
      {
        const double* p = pd->GetPoint(ids->GetId(std::min<vtkIdType>(k, ids->GetNumberOfIds() - 1)));
        for (int a = 0; a < 3; ++a)
        {
          x[a] += w[k] * p[a];
        }
      }
      const double off = 0.01 * diag * u(g);
      for (int a = 0; a < 3; ++a)
      {
        x[a] += off * d[a] / len;
      }
    }
    else
    {
      const double r = diag * (1 + 9 * u(g));
      for (int a = 0; a < 3; ++a)
      {
        x[a] = c[a] + r * d[a] / len;
      }
    }
  }
  return xs;
}

// Squared distance from x to cell `id` by the cell's own EvaluatePosition (VTK's measure).
inline double CellDistance2(vtkDataSet* pd, vtkIdType id, const double x[3], int* inside = nullptr)
{
  vtkNew<vtkGenericCell> cell;
  pd->GetCell(id, cell);
  double cp[3], pc[3], d2;
  std::vector<double> w(static_cast<size_t>(cell->GetNumberOfPoints())); // a strip has many
  int sub;
  const int r = cell->EvaluatePosition(x, cp, sub, pc, d2, w.data());
  if (inside)
  {
    *inside = r;
  }
  return d2;
}

inline vtkSmartPointer<vtkTriangleGridLocator> Ours(vtkPolyData* pd, int kind)
{
  auto loc = vtkSmartPointer<vtkTriangleGridLocator>::New();
  loc->SetDataSet(pd);
  loc->SetAcceleratorType(kind);
  loc->BuildLocator();
  return loc;
}

inline vtkSmartPointer<vtkPolyData> LoadIf(const std::string& path)
{
  if (!std::ifstream(path).good())
  {
    return nullptr;
  }
  return art::LoadSurface(path);
}

inline vtkSmartPointer<vtkPolyData> StripSphere()
{
  vtkNew<vtkSphereSource> s;
  s.GetPointer()->SetCenter(3, -1, 2);
  s->SetRadius(1.5);
  s->SetThetaResolution(40);
  s->SetPhiResolution(30);
  vtkNew<vtkStripper> strip;
  strip->SetInputConnection(s->GetOutputPort());
  strip->Update();
  return strip->GetOutput();
}

inline vtkSmartPointer<vtkPolyData> QuadPlane()
{
  vtkNew<vtkPlaneSource> p;
  p->SetOrigin(0, 0, 0);
  p->SetPoint1(4, 1, 0);
  p->SetPoint2(-1, 3, 2);
  p->SetResolution(17, 13);
  p->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION); // float points make the quads bend
  p->Update();
  return p->GetOutput();
}} // namespace arttest

#endif
