#include "BisectionMesh.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace art
{
void BisectionMesh::InitKuhn(const int dims[3], const int cubes[3])
{
  Verts.clear();
  Parent.clear();
  Quarter.clear();
  Tets.clear();
  Tag.clear();
  Gen.clear();
  Versions.clear();
  VertexTets.clear();
  EdgeSplits = false;
  Moved = false;
  int n[3];
  std::vector<int64_t> ticks[3];
  for (int a = 0; a < 3; ++a)
  {
    n[a] = std::max(1, std::min(cubes[a], dims[a] - 1));
    for (int i = 0; i <= n[a]; ++i)
    {
      const long long idx = std::llround(double(i) * (dims[a] - 1) / n[a]);
      ticks[a].push_back(idx * Scale);
    }
  }
  auto vid = [&](int i, int j, int k) { return i + (n[0] + 1) * (j + (n[1] + 1) * k); };
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i)
      {
        Verts.push_back({ ticks[0][i], ticks[1][j], ticks[2][k] });
        Parent.push_back({ -1, -1 });
        Quarter.push_back(2);
      }
  VertexTets.resize(Verts.size());
  // The six permutations of the axes give the six Kuhn tets along the diagonal (0,0,0)-(1,1,1);
  // every box uses the same six, so shared faces are split the same way from both sides.
  static const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 },
    { 2, 0, 1 }, { 2, 1, 0 } };
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        for (const auto& p : perms)
        {
          int c[3] = { i, j, k };
          std::array<int, 4> t;
          t[0] = vid(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s)
          {
            ++c[p[s]];
            t[s + 1] = vid(c[0], c[1], c[2]);
          }
          const int id = static_cast<int>(Tets.size());
          Tets.push_back(t);
          Tag.push_back(3);
          Gen.push_back(0);
          Versions.push_back(0);
          for (int v : t)
          {
            VertexTets[v].push_back(id);
          }
        }
}

void BisectionMesh::InitFromTets(std::vector<LatticePoint> points, const std::vector<std::array<int, 4>>& tets)
{
  const int nv = static_cast<int>(points.size());
  Verts = std::move(points);
  Parent.assign(Verts.size(), { -1, -1 });
  Quarter.assign(Verts.size(), 2);
  Tets = tets;
  Tag.assign(Tets.size(), 3);
  Gen.assign(Tets.size(), 0);
  Versions.assign(Tets.size(), 0);
  VertexTets.assign(Verts.size(), {});
  for (int t = 0; t < static_cast<int>(Tets.size()); ++t)
  {
    for (int v : Tets[t])
    {
      if (v < 0 || v >= nv)
      {
        throw Error("internal: a tet names vertex " + std::to_string(v) + " of " + std::to_string(nv));
      }
      VertexTets[v].push_back(t);
    }
  }
  EdgeSplits = false;
  Moved = true;
}

std::array<int, 2> BisectionMesh::RefinementEdge(int t) const
{
  const auto& v = Tets[t];
  const int a = v[0], b = v[Tag[t]];
  return { std::min(a, b), std::max(a, b) };
}

bool BisectionMesh::CanBisect(int t) const
{
  const auto e = RefinementEdge(t);
  const LatticePoint &p = Verts[e[0]], &q = Verts[e[1]];
  return ((p.x + q.x) % 2 == 0) && ((p.y + q.y) % 2 == 0) && ((p.z + q.z) % 2 == 0);
}

double BisectionMesh::RefinementEdgeLength2(int t) const
{
  const auto e = RefinementEdge(t);
  const LatticePoint &p = Verts[e[0]], &q = Verts[e[1]];
  const double s = 1.0 / static_cast<double>(Scale);
  const double dx = (q.x - p.x) * s, dy = (q.y - p.y) * s, dz = (q.z - p.z) * s;
  return dx * dx + dy * dy + dz * dz;
}

const int BisectionMesh::EdgeCorners[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };

double BisectionMesh::EdgeLength2(int a, int b) const
{
  const LatticePoint &p = Verts[a], &q = Verts[b];
  const double s = 1.0 / static_cast<double>(Scale);
  const double dx = (q.x - p.x) * s, dy = (q.y - p.y) * s, dz = (q.z - p.z) * s;
  return dx * dx + dy * dy + dz * dz;
}

bool BisectionMesh::CanSplitEdge(int a, int b, int quarters) const
{
  const LatticePoint &p = Verts[a], &q = Verts[b];
  if (quarters == 2)
  {
    return ((p.x + q.x) % 2 == 0) && ((p.y + q.y) % 2 == 0) && ((p.z + q.z) % 2 == 0);
  }
  return (quarters == 1 || quarters == 3) && (q.x - p.x) % 4 == 0 && (q.y - p.y) % 4 == 0 && (q.z - p.z) % 4 == 0;
}

void BisectionMesh::SplitEdge(int a, int b, std::vector<int>& touched, int quarters)
{
  if (Moved)
  {
    throw Error("internal: edge split after vertex relocation");
  }
  if (a == b || !CanSplitEdge(a, b, quarters))
  {
    throw Error("refinement reached the lattice resolution");
  }
  std::vector<int> star;
  TetsWithEdge(a, b, star);
  if (star.empty())
  {
    throw Error("internal: split of an edge that is in no tet");
  }
  EdgeSplits = true;
  const LatticePoint &p = Verts[a], &q = Verts[b];
  const int mid = static_cast<int>(Verts.size());
  // Exact: CanSplitEdge made (q - p) * quarters a multiple of 4.
  Verts.push_back({ p.x + (q.x - p.x) * quarters / 4, p.y + (q.y - p.y) * quarters / 4,
    p.z + (q.z - p.z) * quarters / 4 });
  Parent.push_back({ std::min(a, b), std::max(a, b) });
  Quarter.push_back(static_cast<uint8_t>(a < b ? quarters : 4 - quarters));
  VertexTets.emplace_back();
  for (int t : star)
  {
    // Child 1 (slot t) keeps a, b -> mid; child 2 (new slot) keeps b, a -> mid. Replacing one
    // end of the edge by its midpoint halves the volume and keeps its sign.
    const std::array<int, 4> x = Tets[t];
    std::array<int, 4> c1 = x, c2 = x;
    for (int i = 0; i < 4; ++i)
    {
      if (x[i] == b)
      {
        c1[i] = mid;
      }
      if (x[i] == a)
      {
        c2[i] = mid;
      }
    }
    const int n = static_cast<int>(Tets.size());
    Tets[t] = c1;
    ++Gen[t];
    ++Versions[t];
    Tets.push_back(c2);
    Tag.push_back(Tag[t]);
    Gen.push_back(Gen[t]);
    Versions.push_back(0);
    for (int v : x)
    {
      auto& lst = VertexTets[v];
      if (v == b)
      {
        *std::find(lst.begin(), lst.end(), t) = n;
      }
      else if (v != a)
      {
        lst.push_back(n);
      }
    }
    VertexTets[mid].push_back(t);
    VertexTets[mid].push_back(n);
    touched.push_back(t);
    touched.push_back(n);
  }
}

void BisectionMesh::TetsWithEdge(int a, int b, std::vector<int>& out) const
{
  out.clear();
  for (int t : VertexTets[a])
  {
    const auto& v = Tets[t];
    if (v[0] == b || v[1] == b || v[2] == b || v[3] == b)
    {
      out.push_back(t);
    }
  }
  std::sort(out.begin(), out.end()); // a fixed order keeps new vertex and tet numbers deterministic
}

void BisectionMesh::Refine(int t, std::vector<int>& touched)
{
  if (EdgeSplits || Moved)
  {
    throw Error(EdgeSplits ? "internal: newest-vertex bisection after free edge splits"
                           : "internal: bisection after vertex relocation");
  }
  RefineRecursive(t, touched, 0);
}

void BisectionMesh::RefineRecursive(int t, std::vector<int>& touched, int depth)
{
  if (depth > 256)
  {
    throw Error("bisection closure did not terminate (incompatible tagging)");
  }
  std::vector<int> patch;
  for (;;)
  {
    const auto e = RefinementEdge(t);
    TetsWithEdge(e[0], e[1], patch);
    int other = -1;
    for (int s : patch)
    {
      if (RefinementEdge(s) != e)
      {
        other = s;
        break;
      }
    }
    if (other < 0)
    {
      break;
    }
    // A neighbour around our edge would be cut elsewhere: cut it first (Maubach's closure);
    // it is of an older generation, so this recursion ends.
    RefineRecursive(other, touched, depth + 1);
  }
  const auto e = RefinementEdge(t);
  for (int s : patch)
  {
    if (!CanBisect(s))
    {
      throw Error("refinement reached the lattice resolution");
    }
  }
  const LatticePoint &p = Verts[e[0]], &q = Verts[e[1]];
  const int mid = static_cast<int>(Verts.size());
  Verts.push_back({ (p.x + q.x) / 2, (p.y + q.y) / 2, (p.z + q.z) / 2 });
  Parent.push_back({ e[0], e[1] });
  Quarter.push_back(2);
  VertexTets.emplace_back();
  for (int s : patch)
  {
    Bisect(s, mid, touched);
  }
}

void BisectionMesh::Bisect(int t, int mid, std::vector<int>& touched)
{
  const std::array<int, 4> x = Tets[t];
  const int k = Tag[t];
  std::array<int, 4> c1 = x, c2;
  c1[k] = mid; // (x0, .., x_{k-1}, z, x_{k+1}, .., x3)
  int o = 0;
  for (int i = 1; i <= k; ++i)
  {
    c2[o++] = x[i];
  }
  c2[o++] = mid; // (x1, .., xk, z, x_{k+1}, .., x3)
  for (int i = k + 1; i < 4; ++i)
  {
    c2[o++] = x[i];
  }
  const uint8_t tag = static_cast<uint8_t>(k > 1 ? k - 1 : 3);
  const int n = static_cast<int>(Tets.size());
  Tets[t] = c1;
  Tag[t] = tag;
  ++Gen[t];
  ++Versions[t];
  Tets.push_back(c2);
  Tag.push_back(tag);
  Gen.push_back(Gen[t]);
  Versions.push_back(0);
  // x0 stays only in c1 (slot t), xk only in c2 (slot n), the others and mid in both.
  for (int i = 1; i < 4; ++i)
  {
    auto& lst = VertexTets[x[i]];
    if (i == k)
    {
      *std::find(lst.begin(), lst.end(), t) = n;
    }
    else
    {
      lst.push_back(n);
    }
  }
  VertexTets[mid].push_back(t);
  VertexTets[mid].push_back(n);
  touched.push_back(t);
  touched.push_back(n);
}
void BisectionMesh::MoveVertex(int v, const LatticePoint& p)
{
  Moved = true;
  Verts[v] = p;
  for (int t : VertexTets[v])
  {
    ++Versions[t];
  }
}
} // namespace art
