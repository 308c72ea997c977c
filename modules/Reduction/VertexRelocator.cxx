#include "VertexRelocator.h"

#include "Error.h"
#include "OpacityImportance.h"
#include "ParallelTiles.h"
#include "Progress.h"
#include "RelocationMoments.h"
#include "VertexVisit.h"
#include "VoxelRaster.h"

#include <algorithm>
#include <vector>

namespace art
{
namespace
{
// The sum of squared (or, weighted, OpacityImportance) errors over every voxel, in tet order:
// the same for any thread count.
double TotalSse(const BisectionMesh& mesh, const VoxelVolume& vol, const std::vector<double>& x,
  const OpacityImportance* imp)
{
  std::vector<double> per(static_cast<size_t>(mesh.NumberOfTets()));
  ForEachRange(mesh.NumberOfTets(), 256, [&](long long t0, long long t1, Counters&) {
    for (int t = static_cast<int>(t0); t < t1; ++t)
    {
      double s = 0;
      LatticePoint P[4];
      double c[4];
      for (int a = 0; a < 4; ++a)
      {
        P[a] = mesh.Vertex(mesh.Tet(t)[a]);
        c[a] = x[mesh.Tet(t)[a]];
      }
      TetRaster r;
      if (!r.Setup(P))
      {
        throw Error("internal: a flat tetrahedron after relocation");
      }
      r.ForEachVoxel(vol.Dims, [&](long long idx, const double* l) {
        const double f = vol.Value(idx), u = c[0] * l[0] + c[1] * l[1] + c[2] * l[2] + c[3] * l[3];
        s += imp ? imp->Error2(idx, f, u) : (f - u) * (f - u);
      });
      per[t] = s;
    }
  });
  double s = 0;
  for (double e : per)
  {
    s += e;
  }
  return s;
}

// Vertices with no tet in common neither move nor read each other's place or value: the greedy
// colouring (in vertex order) whose classes are relaxed each in parallel, with the same result for
// any thread count.
std::vector<std::vector<int>> ColourClasses(const BisectionMesh& mesh)
{
  const int nv = mesh.NumberOfVertices();
  std::vector<int> colour(static_cast<size_t>(nv), -1), stamp;
  std::vector<std::vector<int>> classes;
  for (int v = 0; v < nv; ++v)
  {
    stamp.assign(classes.size() + 1, 0);
    for (int t : mesh.TetsAround(v))
    {
      for (int w : mesh.Tet(t))
      {
        if (colour[w] >= 0)
        {
          stamp[colour[w]] = 1;
        }
      }
    }
    int c = 0;
    while (stamp[c])
    {
      ++c;
    }
    colour[v] = c;
    if (c == static_cast<int>(classes.size()))
    {
      classes.emplace_back();
    }
    classes[c].push_back(v);
  }
  return classes;
}

// One Gauss-Seidel sweep over the active vertices, class by class; `moved` marks who moved.
void Sweep(const std::vector<std::vector<int>>& classes, const VertexVisit& visit, const std::vector<char>& active,
  std::vector<char>& moved, Progress* progress)
{
  for (const auto& cls : classes)
  {
    if (progress)
    {
      if (progress->Cancelled())
      {
        throw Error("cancelled");
      }
      progress->Advance(double(cls.size()));
    }
    ForEachRange(static_cast<long long>(cls.size()), 8, [&](long long b, long long e, Counters&) {
      VertexVisit::Scratch sc;
      for (long long i = b; i < e; ++i)
      {
        const int v = cls[i];
        moved[v] = active[v] && visit.Visit(v, sc) ? 1 : 0;
      }
    });
  }
}
} // namespace

RelocationStats VertexRelocator::Relocate(BisectionMesh& mesh, const VoxelVolume& volume, std::vector<double>& x,
  const RelocationOptions& options, const OpacityImportance* importance, Progress* progress)
{
  const int nv = mesh.NumberOfVertices();
  if (static_cast<int>(x.size()) != nv)
  {
    throw Error("internal: relocation needs one value per vertex");
  }
  RelocationStats s;
  // The set-up's voxel passes (the weights when weighted, the moments) count half a sweep each:
  // on a large volume they take seconds, which the progress must show.
  const double passUnits = 0.5 * nv;
  if (progress)
  {
    progress->Begin("relocate", (importance ? 2 : 1) * passUnits + double(options.Sweeps) * nv);
  }
  if (options.MeasureSse)
  {
    s.SseBefore = TotalSse(mesh, volume, x, importance);
  }
  RelocationMoments moments(volume, importance);
  moments.Compute(mesh, x, progress, passUnits);
  mesh.StopRefinement();
  const VertexVisit visit(mesh, volume, x, options, moments);
  const std::vector<std::vector<int>> classes = ColourClasses(mesh);
  // Active set: a sweep visits the vertices that moved, or a neighbour of which moved, last sweep.
  std::vector<char> active(static_cast<size_t>(nv), 1), next(static_cast<size_t>(nv), 0), moved(static_cast<size_t>(nv), 0);
  for (int sweep = 0; sweep < options.Sweeps; ++sweep)
  {
    Sweep(classes, visit, active, moved, progress);
    long long count = 0;
    std::fill(next.begin(), next.end(), 0);
    for (int v = 0; v < nv; ++v)
    {
      s.Visited += active[v];
      if (moved[v])
      {
        ++count;
        for (int t : mesh.TetsAround(v))
        {
          for (int w : mesh.Tet(t))
          {
            next[w] = 1;
          }
        }
      }
    }
    active.swap(next);
    s.Moved += count;
    ++s.Sweeps;
    if (count == 0)
    {
      break;
    }
  }
  if (options.MeasureSse)
  {
    s.SseAfter = TotalSse(mesh, volume, x, importance);
  }
  if (progress)
  {
    progress->End();
  }
  return s;
}
} // namespace art
