#include "EntryFinder.h"

#include "ParallelTiles.h"

#include <algorithm>
#include <cmath>

namespace art
{
namespace
{
constexpr int B = 4; // bucket size in pixels
constexpr double Slack = 0.01; // pixels
}

EntryFinder::EntryFinder(const TetMesh& m)
  : M(m), F(m.BoundaryFaces())
{
  Global.resize(F.size());
  for (std::size_t i = 0; i < Global.size(); ++i)
  {
    Global[i] = static_cast<int>(i);
  }
}

EntryFinder::EntryFinder(const TetMesh& m, const Camera& cam, const std::vector<std::array<int, 2>>* faces)
  : M(m), F(faces ? *faces : m.BoundaryFaces()), Region(faces != nullptr), W(cam.Width()), H(cam.Height()),
    Bucketed(true), Eye(cam.Position()), Fwd(cam.Forward()), DepthMargin(1e-9 * m.Bounds().Diagonal())
{
  BW = (W + B - 1) / B;
  BH = (H + B - 1) / B;
  // Recover the image-plane axes (scaled by the half extents) from the camera's own rays, so the
  // projection below is exactly the inverse of Camera::Generate.
  const Vec3 eye = Eye, fwd = Fwd;
  const bool par = cam.IsParallel();
  // The image's centre may sit off the view axis (a window centre): its offset C is taken off.
  Vec3 RW, UH, C;
  {
    auto plane = [&](const Ray& r) { return par ? r.org - eye : r.dir / Dot(r.dir, fwd) - fwd; };
    C = plane(cam.Generate(0.5 * W - 0.5, 0.5 * H - 0.5));
    RW = plane(cam.Generate(W - 0.5, 0.5 * H - 0.5)) - C;
    UH = plane(cam.Generate(0.5 * W - 0.5, -0.5)) - C;
  }
  const double rr = Dot(RW, RW), uu = Dot(UH, UH), cr = Dot(C, RW), cu = Dot(C, UH);
  const auto& bf = F;
  // Each face's bucket rectangle x0, x1, y0, y1 (inclusive; empty: none) and slot, in parallel.
  std::vector<std::array<int, 4>> rect(bf.size(), { 1, 0, 1, 0 });
  std::vector<EntrySlot> slot(bf.size());
  std::vector<char> global(bf.size(), 0);
  const double nearZ = 1e-9 * std::max(M.Bounds().Diagonal(), 1e-300);
  ForEachRange(static_cast<long long>(bf.size()), 4096, [&](long long b0, long long b1, Counters&) {
    for (long long b = b0; b < b1; ++b)
    {
      const auto& v = M.Tet(bf[b][0]);
      const int* fv = TetMesh::FaceVertex[bf[b][1]];
      const Vec3 &p0 = M.PointsArray()[v[fv[0]]], &p1 = M.PointsArray()[v[fv[1]]], &p2 = M.PointsArray()[v[fv[2]]];
      const Vec3 n = Cross(p1 - p0, p2 - p0); // outward (FaceVertex order); only its sign is used
      if ((par ? Dot(fwd, n) : Dot(p0 - eye, n)) > 0)
      {
        continue; // back-facing: no ray from this camera enters through it
      }
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300, depth = 1e300;
      Vec3 q[3];
      double z[3];
      int near = 0, back = 0;
      for (int k = 0; k < 3; ++k)
      {
        q[k] = M.PointsArray()[v[fv[k]]] - eye;
        const double d = Dot(q[k], fwd);
        depth = std::min(depth, d);
        z[k] = par ? 1.0 : d;
        near += z[k] <= nearZ;
        back += z[k] < 0;
      }
      if (back == 3)
      {
        continue; // behind the eye's plane: the camera's rays (forward, from the eye) never get there
      }
      if (near > 0)
      {
        global[b] = 1; // across the eye's plane: no screen box, every ray tests it
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        const double xn = (Dot(q[k], RW) / z[k] - cr) / rr, yn = (Dot(q[k], UH) / z[k] - cu) / uu;
        const double px = (xn + 1) * 0.5 * W - 0.5, py = (1 - yn) * 0.5 * H - 0.5;
        x0 = std::min(x0, px), x1 = std::max(x1, px), y0 = std::min(y0, py), y1 = std::max(y1, py);
      }
      // Rays go through pixel centres and the test itself is exact, so the box needs slack only
      // for the projection's rounding against Camera::Generate's (far below Slack).
      x0 -= Slack, x1 += Slack, y0 -= Slack, y1 += Slack;
      const int bx0 = static_cast<int>(std::floor(x0 / B)), bx1 = static_cast<int>(std::floor(x1 / B));
      const int by0 = static_cast<int>(std::floor(y0 / B)), by1 = static_cast<int>(std::floor(y1 / B));
      if (bx1 < 0 || by1 < 0 || bx0 >= BW || by0 >= BH)
      {
        continue;
      }
      rect[b] = { std::max(bx0, 0), std::min(bx1, BW - 1), std::max(by0, 0), std::min(by1, BH - 1) };
      // Rounded outward (the depth down): a face projected far off screen (near the eye's plane)
      // has coordinates beyond float's integer precision.
      auto down = [](double x) { const float f = static_cast<float>(x); return f > x ? std::nextafter(f, -HUGE_VALF) : f; };
      auto up = [](double x) { const float f = static_cast<float>(x); return f < x ? std::nextafter(f, HUGE_VALF) : f; };
      slot[b] = { down(x0), up(x1), down(y0), up(y1), down(depth), static_cast<int>(b),
        { v[fv[0]], v[fv[1]], v[fv[2]] } };
    }
  }, nullptr);
  Begin.assign(static_cast<std::size_t>(BW) * BH + 1, 0);
  for (const auto& r : rect)
  {
    for (int y = r[2]; y <= r[3]; ++y)
    {
      for (int x = r[0]; x <= r[1]; ++x)
      {
        ++Begin[y * BW + x + 1];
      }
    }
  }
  for (std::size_t k = 1; k < Begin.size(); ++k)
  {
    Begin[k] += Begin[k - 1];
  }
  Slots.resize(Begin.back());
  std::vector<int> fill(Begin.begin(), Begin.end() - 1);
  for (std::size_t b = 0; b < rect.size(); ++b)
  {
    const auto& r = rect[b];
    for (int y = r[2]; y <= r[3]; ++y)
    {
      for (int x = r[0]; x <= r[1]; ++x)
      {
        Slots[fill[y * BW + x]++] = slot[b];
      }
    }
    if (global[b])
    {
      Global.push_back(static_cast<int>(b));
    }
  }
  // Nearest first (ties by face: the same order for any thread count).
  ForEachRange(static_cast<long long>(BW) * BH, 64, [&](long long k0, long long k1, Counters&) {
    for (long long k = k0; k < k1; ++k)
    {
      std::sort(Slots.begin() + Begin[k], Slots.begin() + Begin[k + 1],
        [](const EntrySlot& a, const EntrySlot& b) { return a.z < b.z || (a.z == b.z && a.face < b.face); });
    }
  }, nullptr);
}

bool EntryFinder::Empty(int x0, int y0, int x1, int y1) const
{
  if (!Bucketed || !Global.empty() || x0 < 0 || y0 < 0 || x1 > W || y1 > H)
  {
    return false;
  }
  for (int by = y0 / B; by <= (y1 - 1) / B; ++by)
  {
    for (int bx = x0 / B; bx <= (x1 - 1) / B; ++bx)
    {
      const int k = by * BW + bx;
      if (Begin[k + 1] > Begin[k])
      {
        return false;
      }
    }
  }
  return true;
}

bool EntryFinder::Test(const TetWalker& w, const ProjectedWalker* pw, double tmin, const EntrySlot& sl, Entry& e) const
{
  const bool in = pw ? pw->CrossesFace(sl.v[0], sl.v[1], sl.v[2], -1, e.x) : w.CrossesFace(sl.v[0], sl.v[1], sl.v[2], -1, e.x);
  if (!in || e.x.t < tmin)
  {
    return false;
  }
  e.face = sl.face;
  return true;
}

bool EntryFinder::Test(const TetWalker& w, const ProjectedWalker* pw, double tmin, int b, Entry& e) const
{
  const auto& bf = F[b];
  if (!(pw ? pw->Crosses(bf[0], bf[1], -1, e.x) : w.Crosses(bf[0], bf[1], -1, e.x)) || e.x.t < tmin)
  {
    return false;
  }
  e.face = b;
  return true;
}

void EntryFinder::Find(const TetWalker& w, const Ray& r, int px, int py, bool all,
  std::vector<Entry>& out, int& hint, Counters& c, const ProjectedWalker* pw) const
{
  out.clear();
  if (all || Region)
  {
    EntryCursor cur;
    Start(cur, w, r, px, py, c, pw);
    for (const Entry* e = cur.Front(); e; cur.Pop(), e = cur.Front())
    {
      out.push_back(*e);
    }
    return;
  }
  // Convex: the one entry face. The previous ray's, then one step of the walk over its neighbours.
  Entry e;
  if (hint >= 0)
  {
    if (Test(w, pw, r.tmin, hint, e))
    {
      out.push_back(e);
      return;
    }
    for (int n : M.BoundaryAdjacency(hint))
    {
      if (n >= 0 && Test(w, pw, r.tmin, n, e))
      {
        out.push_back(e);
        hint = n;
        return;
      }
    }
  }
  ++c.entrySearches;
  // A bucket's faces are first checked against the pixel by their screen box (with slack): most
  // of them miss it, and the exact test costs ten times more.
  if (Bucketed && px >= 0 && py >= 0 && px < W && py < H)
  {
    const float fx = static_cast<float>(px), fy = static_cast<float>(py);
    const int k = (py / B) * BW + px / B;
    for (const EntrySlot *sl = Slots.data() + Begin[k], *end = Slots.data() + Begin[k + 1]; sl != end; ++sl)
    {
      if (fx >= sl->x0 && fx <= sl->x1 && fy >= sl->y0 && fy <= sl->y1 && Test(w, pw, r.tmin, *sl, e))
      {
        out.push_back(e);
        hint = e.face;
        return;
      }
    }
  }
  for (int b : Global)
  {
    if (Test(w, pw, r.tmin, b, e))
    {
      out.push_back(e);
      hint = e.face;
      return;
    }
  }
}

void EntryFinder::Start(EntryCursor& cur, const TetWalker& w, const Ray& r, int px, int py, Counters& c,
  const ProjectedWalker* pw) const
{
  ++c.entrySearches;
  cur.Pending.clear();
  cur.Head = 0;
  cur.F = this, cur.W = &w, cur.PW = pw;
  cur.TMin = r.tmin;
  cur.Next = cur.End = nullptr;
  Entry e;
  for (int b : Global)
  {
    if (Test(w, pw, r.tmin, b, e))
    {
      cur.Insert(e);
    }
  }
  if (!Bucketed || px < 0 || py < 0 || px >= W || py >= H)
  {
    return;
  }
  const int k = (py / B) * BW + px / B;
  cur.Next = Slots.data() + Begin[k];
  cur.End = Slots.data() + Begin[k + 1];
  cur.Fx = static_cast<float>(px), cur.Fy = static_cast<float>(py);
  // Faces far beyond the nearest entry found need no test yet (UpdateStop). The slack covers the
  // crossings' rounding (relative 1e-12 at worst), so a face is never left behind an entry it
  // comes before.
  const double dz = Dot(r.dir, Fwd);
  cur.Prune = dz > 0;
  cur.InvDz = cur.Prune ? 1.0 / dz : 0.0;
  cur.Z0 = Dot(r.org - Eye, Fwd);
  cur.Slack = DepthMargin * cur.InvDz;
  cur.UpdateStop();
}

void EntryCursor::Insert(const Entry& e)
{
  Pending.push_back(e);
  for (std::size_t i = Pending.size() - 1; i > Head && Pending[i].x.t < Pending[i - 1].x.t; --i)
  {
    std::swap(Pending[i], Pending[i - 1]);
  }
  UpdateStop();
}

void EntryCursor::UpdateStop()
{
  // A face's points lie at depth z >= its slot's z, where the ray is at t >= (z - Z0) / Dz: a slot
  // whose t would pass the next entry's by the slack lies behind it. In depth, with a relative
  // margin for the division's rounding (far below the slack).
  ZStop = HUGE_VAL;
  if (Prune && Head < Pending.size())
  {
    const double t = Pending[Head].x.t;
    const double stop = Z0 + (t + Slack + 1e-9 * std::fabs(t)) / InvDz;
    ZStop = stop + 1e-12 * std::fabs(stop);
  }
}

void EntryCursor::Scan()
{
  UpdateStop(); // the caller may have taken the head since
  Entry e;
  for (; Next != End; ++Next)
  {
    if (Next->z > ZStop)
    {
      return; // this face and every later one lie behind the next entry
    }
    if (Fx >= Next->x0 && Fx <= Next->x1 && Fy >= Next->y0 && Fy <= Next->y1 && F->Test(*W, PW, TMin, *Next, e))
    {
      Insert(e);
    }
  }
}
} // namespace art
