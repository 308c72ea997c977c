// TetRayCaster's empty-space region (RenderSettings::skipEmpty): which tets can show, the face
// links with those into the others cut, and the faces through which rays enter the shown tets.
#include "TetRayCaster.h"

#include "ParallelTiles.h"

#include <algorithm>
#include <atomic>

namespace art
{
void TetRayCaster::BuildRegion()
{
  // A tet's scalars lie between its vertices' (linear inside), so a tet whose range the transfer
  // function leaves transparent and no iso-value falls in adds nothing to any ray; nor does one
  // wholly on the clipped side of a plane. Rebuilt only when the opacity nodes, the iso-values or
  // the planes change (a mapper sets its settings every frame).
  std::vector<double> key;
  const bool want = S.skipEmpty && S.mode == RenderSettings::Mode::Composite;
  const std::vector<std::array<double, 4>> none, &culled = S.cullClipped ? S.clipPlanes : none;
  if (want)
  {
    for (const auto& n : S.tf.Nodes())
    {
      key.push_back(n.s), key.push_back(n.tau);
    }
    key.push_back(1e300); // nodes end here
    for (const auto& iso : S.isos)
    {
      key.push_back(iso.value);
    }
    key.push_back(1e300); // iso-values end here
    for (const auto& q : culled)
    {
      key.insert(key.end(), q.begin(), q.end());
    }
  }
  if (Shown.built && key == Shown.key) // an empty key: skipping off
  {
    return;
  }
  Shown = Region();
  Shown.key = key;
  Shown.built = true;
  if (!want)
  {
    return;
  }
  const std::size_t n = M.NumberOfTets();
  Shown.shown.assign(n, 0);
  std::atomic<std::size_t> count{ 0 };
  ForEachRange(static_cast<long long>(n), 4096, [&](long long b, long long e, Counters&) {
    std::size_t local = 0;
    for (long long t = b; t < e; ++t)
    {
      double lo = 1e300, hi = -1e300;
      for (int v : M.Tet(t))
      {
        lo = std::min(lo, M.Scalars()[v]), hi = std::max(hi, M.Scalars()[v]);
      }
      bool show = !S.tf.Transparent(lo, hi);
      for (std::size_t k = 0; k < S.isos.size() && !show; ++k)
      {
        show = S.isos[k].value >= lo && S.isos[k].value <= hi;
      }
      for (std::size_t k = 0; k < culled.size() && show; ++k)
      {
        const auto& q = culled[k];
        bool cut = true; // every corner strictly on the clipped side
        for (int v : M.Tet(t))
        {
          const Vec3& p = M.PointsArray()[v];
          cut = cut && q[0] * p.x + q[1] * p.y + q[2] * p.z + q[3] < 0;
        }
        show = !cut;
      }
      Shown.shown[t] = show;
      local += show;
    }
    count += local;
  }, nullptr);
  if (count == n)
  {
    Shown.shown.clear(); // everything shows: the plain walk, with its coherent convex entries
    return;
  }
  // The region's links and boundary faces, in parallel chunks whose faces join in chunk order
  // (the same list for any thread count).
  Shown.records.resize(n);
  constexpr long long grain = 16384;
  const long long chunks = (static_cast<long long>(n) + grain - 1) / grain;
  std::vector<std::vector<std::array<int, 2>>> faces(static_cast<std::size_t>(chunks));
  ForEachRange(chunks, 1, [&](long long c0, long long c1, Counters&) {
    for (long long c = c0; c < c1; ++c)
    {
      const std::size_t b = static_cast<std::size_t>(c * grain), e = std::min<std::size_t>(n, b + grain);
      for (std::size_t t = b; t < e; ++t)
      {
        Shown.records[t] = M.Record(t);
        if (!Shown.shown[t])
        {
          continue;
        }
        for (int f = 0; f < 4; ++f)
        {
          int& l = Shown.records[t].link[f];
          if (l < 0 || !Shown.shown[TetMesh::LinkTet(l)])
          {
            l = -1;
            faces[static_cast<std::size_t>(c)].push_back({ static_cast<int>(t), f });
          }
        }
      }
    }
  }, nullptr);
  for (const auto& fc : faces)
  {
    Shown.faces.insert(Shown.faces.end(), fc.begin(), fc.end());
  }
  Shown.on = true;
}
} // namespace art
