// The recursive grid's point and box searches (included by RecursiveGrid.h): the nearest-point
// walk searches a grid ring by ring, Chebyshev rings of cells around the cell nearest x; a ring
// can hold nothing nearer than the nearest of its faces' slabs, so the rings stop once that bound
// passes the best distance so far, and within a ring cells beyond it are skipped too.
#ifndef art_RecursiveGridSearch_h
#define art_RecursiveGridSearch_h

namespace art
{
template <class Id, class Visitor>
void RecursiveGrid::NearGrid(const Id* lists, std::uint32_t block, int depth, const double lo[3], const Vec3& x,
  const double& prune2, Visitor& visit, Counters& c) const
{
  const int* n = Dims(depth);
  const double *cs = Cs[depth], *ics = InvCs[depth];
  int ci[3], maxR = 0;
  double out2[3];
  for (int a = 0; a < 3; ++a)
  {
    const double hi = lo[a] + n[a] * cs[a];
    const double o = x[a] < lo[a] ? lo[a] - x[a] : (x[a] > hi ? x[a] - hi : 0.0);
    out2[a] = o * o;
    const double f = std::floor((x[a] - lo[a]) * ics[a]);
    ci[a] = f < 0 ? 0 : (f >= n[a] ? n[a] - 1 : static_cast<int>(f));
    maxR = std::max(maxR, std::max(ci[a], n[a] - 1 - ci[a]));
  }
  auto cell = [&](int i, int j, int k) {
    const double clo[3] = { lo[0] + i * cs[0], lo[1] + j * cs[1], lo[2] + k * cs[2] };
    const double chi[3] = { clo[0] + cs[0], clo[1] + cs[1], clo[2] + cs[2] };
    if (BoxDistance2(clo, chi, x) > prune2)
    {
      return;
    }
    ++c.voxelsVisited;
    const std::uint32_t e = EntryOf(block, (static_cast<std::uint64_t>(k) * n[1] + j) * n[0] + i);
    if (e == Empty)
    {
      return;
    }
    if (e & Child)
    {
      NearGrid(lists, e & ~Child, depth + 1, clo, x, prune2, visit, c);
      return;
    }
    std::uint32_t count;
    const Id* ids = CellLists::Read(lists, e, count);
    visit(ids, count);
  };
  cell(ci[0], ci[1], ci[2]);
  for (int r = 1; r <= maxR; ++r)
  {
    double face2[3][2], gap2[3][2];
    double ring2 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a)
    {
      for (int s = 0; s < 2; ++s)
      {
        const int idx = ci[a] + (s ? r : -r);
        face2[a][s] = std::numeric_limits<double>::infinity();
        if (idx < 0 || idx >= n[a])
        {
          continue;
        }
        const double gap = std::max(0.0, s ? lo[a] + idx * cs[a] - x[a] : x[a] - (lo[a] + (idx + 1) * cs[a]));
        gap2[a][s] = gap * gap;
        face2[a][s] = gap2[a][s] + out2[(a + 1) % 3] + out2[(a + 2) % 3];
        ring2 = std::min(ring2, face2[a][s]);
      }
    }
    if (ring2 > prune2)
    {
      break; // every further ring lies further still
    }
    // Face (a, s) of the ring: axis a at ci[a] -+ r, axes before a strictly inside the ring,
    // axes after it across the whole ring, so each cell of the ring is visited once.
    for (int a = 0; a < 3; ++a)
    {
      for (int s = 0; s < 2; ++s)
      {
        const int idx = ci[a] + (s ? r : -r);
        if (idx < 0 || idx >= n[a] || face2[a][s] > prune2)
        {
          continue;
        }
        int from[3], to[3];
        for (int b = 0; b < 3; ++b)
        {
          if (b == a)
          {
            from[b] = to[b] = idx;
            continue;
          }
          const int in = b < a ? 1 : 0;
          from[b] = std::max(ci[b] - r + in, 0);
          to[b] = std::min(ci[b] + r - in, n[b] - 1);
          // Along b a cell can hold something nearer only within this reach of x: the face's own
          // distance along a and x's distance outside the grid along the third axis are spent.
          const double reach = std::sqrt(std::max(0.0, prune2 - gap2[a][s] - out2[3 - a - b]));
          if (reach < std::numeric_limits<double>::infinity())
          {
            const double l = std::floor((x[b] - reach - lo[b]) * ics[b]);
            const double h = std::floor((x[b] + reach - lo[b]) * ics[b]);
            from[b] = l > from[b] ? static_cast<int>(std::min(l, double(n[b]))) : from[b];
            to[b] = h < to[b] ? static_cast<int>(std::max(h, -1.0)) : to[b];
          }
        }
        for (int k = from[2]; k <= to[2]; ++k)
        {
          for (int j = from[1]; j <= to[1]; ++j)
          {
            for (int i = from[0]; i <= to[0]; ++i)
            {
              cell(i, j, k);
            }
          }
        }
      }
    }
  }
}

template <class Id, class Visitor>
void RecursiveGrid::OverlapGrid(
  const Id* lists, std::uint32_t block, int depth, const double lo[3], const Box3& b, Visitor& visit) const
{
  const int* n = Dims(depth);
  const double *cs = Cs[depth], *ics = InvCs[depth];
  int from[3], to[3];
  for (int a = 0; a < 3; ++a)
  {
    // A little wider than the box: a triangle in a voxel face was put in both voxels, and the
    // exact test follows anyway.
    const double l = std::floor((b.lo[a] - lo[a]) * ics[a] - 1e-6);
    const double h = std::floor((b.hi[a] - lo[a]) * ics[a] + 1e-6);
    if (h < 0 || l >= n[a])
    {
      return;
    }
    from[a] = l < 0 ? 0 : static_cast<int>(l);
    to[a] = h >= n[a] ? n[a] - 1 : static_cast<int>(h);
  }
  for (int k = from[2]; k <= to[2]; ++k)
  {
    for (int j = from[1]; j <= to[1]; ++j)
    {
      for (int i = from[0]; i <= to[0]; ++i)
      {
        const std::uint32_t e = EntryOf(block, (static_cast<std::uint64_t>(k) * n[1] + j) * n[0] + i);
        if (e == Empty)
        {
          continue;
        }
        if (e & Child)
        {
          const double clo[3] = { lo[0] + i * cs[0], lo[1] + j * cs[1], lo[2] + k * cs[2] };
          OverlapGrid(lists, e & ~Child, depth + 1, clo, b, visit);
          continue;
        }
        std::uint32_t count;
        const Id* ids = CellLists::Read(lists, e, count);
        visit(ids, count);
      }
    }
  }
}
} // namespace art

#endif
