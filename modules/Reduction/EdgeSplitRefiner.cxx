#include "EdgeSplitRefiner.h"

#include "ParallelTiles.h"

#include <algorithm>
#include <utility>

namespace art
{
bool EdgeSplitRefiner::CanRefine(const BisectionMesh& mesh, int t, double minEdge2)
{
  const auto& v = mesh.Tet(t);
  for (const auto& c : BisectionMesh::EdgeCorners)
  {
    if (mesh.EdgeLength2(v[c[0]], v[c[1]]) >= minEdge2 && mesh.CanSplitEdge(v[c[0]], v[c[1]]))
    {
      return true;
    }
  }
  return false;
}

double EdgeSplitRefiner::Gain(const BisectionMesh& mesh, int a, int b, const std::vector<uint32_t>& version,
  const std::vector<EdgeSplitMoments>& moments, const std::vector<double>& x, double minEdge2, std::vector<int>& star,
  bool* fresh, int* quarters)
{
  mesh.TetsWithEdge(a, b, star);
  const int nt = static_cast<int>(version.size());
  constexpr int NP = EdgeSplitMoments::Positions;
  double S[NP] = {}, Q[NP] = {};
  bool all = true;
  for (int s : star)
  {
    if (s >= nt || mesh.Version(s) != version[s])
    {
      all = false;
      continue;
    }
    const auto& w = mesh.Tet(s);
    int ia = 0, ib = 0;
    for (int i = 0; i < 4; ++i)
    {
      ia = w[i] == a ? i : ia;
      ib = w[i] == b ? i : ib;
    }
    for (int k = 0; k < 6; ++k)
    {
      const int* e = BisectionMesh::EdgeCorners[k];
      const bool same = e[0] == ia && e[1] == ib;
      if (same || (e[0] == ib && e[1] == ia))
      {
        const double c[4] = { x[w[0]], x[w[1]], x[w[2]], x[w[3]] };
        for (int q = 0; q < NP; ++q)
        {
          const int qs = same ? q : NP - 1 - q; // this tet lists the edge from b: t -> 1 - t
          S[q] += moments[s].S(qs, k, c);
          Q[q] += moments[s].Q[qs][k];
        }
      }
    }
  }
  if (fresh)
  {
    *fresh = all;
  }
  // The midpoint unless a quarter point (where the lattice has one) removes more: a vertex can
  // then sit nearer a surface.
  double best = Q[1] > 0 ? S[1] * S[1] / Q[1] : 0.0;
  int bestQ = 2;
  const bool quarterPoints = mesh.EdgeLength2(a, b) >= 4.0 * minEdge2;
  for (int q : { 0, 2 })
  {
    if (!quarterPoints || !mesh.CanSplitEdge(a, b, q + 1))
    {
      continue;
    }
    const double g = Q[q] > 0 ? S[q] * S[q] / Q[q] : 0.0;
    if (g > best)
    {
      best = g;
      bestQ = q + 1;
    }
  }
  if (quarters)
  {
    *quarters = bestQ;
  }
  // Per added tet, because budgets count tets: a high-valence edge costs more.
  return best / static_cast<double>(star.size());
}

void EdgeSplitRefiner::RefineLevel(BisectionMesh& mesh, const std::vector<int>& candidates,
  const std::vector<uint32_t>& version, const std::vector<EdgeSplitMoments>& moments, const std::vector<double>& x,
  double minEdge2, long long target, std::vector<int>& touched)
{
  // The candidates' edges are ranked together, rather than each worst tet taking its best edge:
  // a lower error at the same tets.
  std::vector<std::pair<int, int>> edges;
  for (int t : candidates)
  {
    const auto& v = mesh.Tet(t);
    for (const auto& c : BisectionMesh::EdgeCorners)
    {
      const int a = std::min(v[c[0]], v[c[1]]), b = std::max(v[c[0]], v[c[1]]);
      if (mesh.EdgeLength2(a, b) >= minEdge2 && mesh.CanSplitEdge(a, b))
      {
        edges.emplace_back(a, b);
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  struct Ranked
  {
    double gain;
    int a, b, quarters;
  };
  std::vector<Ranked> ranked(edges.size());
  ForEachRange(static_cast<long long>(edges.size()), 256, [&](long long i0, long long i1, Counters&) {
    std::vector<int> star;
    for (long long i = i0; i < i1; ++i)
    {
      int q = 2;
      const double g = Gain(mesh, edges[i].first, edges[i].second, version, moments, x, minEdge2, star, nullptr, &q);
      ranked[i] = { g, edges[i].first, edges[i].second, q };
    }
  });
  std::sort(ranked.begin(), ranked.end(), [](const Ranked& p, const Ranked& q) {
    return p.gain != q.gain ? p.gain > q.gain : (p.a != q.a ? p.a < q.a : p.b < q.b);
  });
  std::vector<int> star;
  for (const Ranked& e : ranked)
  {
    bool fresh = false;
    Gain(mesh, e.a, e.b, version, moments, x, minEdge2, star, &fresh);
    if (!fresh)
    {
      continue;
    }
    mesh.SplitEdge(e.a, e.b, touched, e.quarters);
    if (mesh.NumberOfTets() >= target)
    {
      break;
    }
  }
}
} // namespace art
