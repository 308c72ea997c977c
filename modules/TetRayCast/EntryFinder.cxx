#include "EntryFinder.h"

#include <algorithm>
#include <cmath>

namespace art
{
namespace
{
constexpr int B = 8; // bucket size in pixels
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
    Bucketed(true)
{
  BW = (W + B - 1) / B;
  BH = (H + B - 1) / B;
  // Recover the image-plane axes (scaled by the half extents) from the camera's own rays, so the
  // projection below is exactly the inverse of Camera::Generate.
  const Vec3 eye = cam.Position(), fwd = cam.Forward();
  const bool par = cam.IsParallel();
  Vec3 RW, UH;
  {
    const Ray rx = cam.Generate(W - 0.5, 0.5 * H - 0.5), ry = cam.Generate(0.5 * W - 0.5, -0.5);
    RW = par ? rx.org - eye : rx.dir / Dot(rx.dir, fwd) - fwd;
    UH = par ? ry.org - eye : ry.dir / Dot(ry.dir, fwd) - fwd;
  }
  const double rr = Dot(RW, RW), uu = Dot(UH, UH);
  const auto& bf = F;
  std::vector<std::array<int, 4>> rect(bf.size(), { 1, 0, 1, 0 }); // bucket x0, x1, y0, y1 (inclusive)
  std::vector<char> global(bf.size(), 0);
  Box.resize(bf.size());
  const double nearZ = 1e-9 * std::max(M.Bounds().Diagonal(), 1e-300);
  for (std::size_t b = 0; b < bf.size(); ++b)
  {
    const auto& v = M.Tet(bf[b][0]);
    const int* fv = TetMesh::FaceVertex[bf[b][1]];
    const TetMesh::Plane pl = Region ? M.FacePlane(bf[b][0], bf[b][1]) : M.BoundaryPlane(b);
    const Vec3& p0 = M.PointsArray()[v[fv[0]]];
    if ((par ? Dot(fwd, pl.n) : Dot(p0 - eye, pl.n)) > 0)
    {
      continue; // back-facing: no ray from this camera enters through it
    }
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    Vec3 q[3];
    double z[3];
    int near = 0, back = 0;
    for (int k = 0; k < 3; ++k)
    {
      q[k] = M.PointsArray()[v[fv[k]]] - eye;
      z[k] = par ? 1.0 : Dot(q[k], fwd);
      near += z[k] <= nearZ;
      back += z[k] < 0;
    }
    if (back == 3)
    {
      continue; // behind the eye's plane: the camera's rays (forward, from the eye) never get there
    }
    const bool behind = near > 0; // across the eye's plane: no screen box, every ray tests it
    for (int k = 0; k < 3 && !behind; ++k)
    {
      const double xn = Dot(q[k], RW) / (rr * z[k]), yn = Dot(q[k], UH) / (uu * z[k]);
      const double px = (xn + 1) * 0.5 * W - 0.5, py = (1 - yn) * 0.5 * H - 0.5;
      x0 = std::min(x0, px), x1 = std::max(x1, px), y0 = std::min(y0, py), y1 = std::max(y1, py);
    }
    if (behind)
    {
      global[b] = 1;
      continue;
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
    // Rounded outward: a face projected far off screen (near the eye's plane) has coordinates
    // beyond float's integer precision.
    auto down = [](double x) { const float f = static_cast<float>(x); return f > x ? std::nextafter(f, -HUGE_VALF) : f; };
    auto up = [](double x) { const float f = static_cast<float>(x); return f < x ? std::nextafter(f, HUGE_VALF) : f; };
    Box[b] = { down(x0), up(x1), down(y0), up(y1) };
  }
  Start.assign(static_cast<std::size_t>(BW) * BH + 1, 0);
  for (const auto& r : rect)
  {
    for (int y = r[2]; y <= r[3]; ++y)
    {
      for (int x = r[0]; x <= r[1]; ++x)
      {
        ++Start[y * BW + x + 1];
      }
    }
  }
  for (std::size_t k = 1; k < Start.size(); ++k)
  {
    Start[k] += Start[k - 1];
  }
  Faces.resize(Start.back());
  std::vector<int> fill(Start.begin(), Start.end() - 1);
  for (std::size_t b = 0; b < rect.size(); ++b)
  {
    const auto& r = rect[b];
    for (int y = r[2]; y <= r[3]; ++y)
    {
      for (int x = r[0]; x <= r[1]; ++x)
      {
        Faces[fill[y * BW + x]++] = static_cast<int>(b);
      }
    }
    if (global[b])
    {
      Global.push_back(static_cast<int>(b));
    }
  }
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
      if (Start[k + 1] > Start[k])
      {
        return false;
      }
    }
  }
  return true;
}

bool EntryFinder::Test(const TetWalker& w, const ProjectedWalker* pw, const Ray& r, int b, Entry& e) const
{
  const auto& bf = F[b];
  if (!(pw ? pw->Crosses(bf[0], bf[1], -1, e.x) : w.Crosses(bf[0], bf[1], -1, e.x)) || e.x.t < r.tmin)
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
  Entry e;
  all = all || Region;
  if (!all && hint >= 0)
  {
    // Coherence: the previous ray's entry face, then one step of the walk over its neighbours.
    if (Test(w, pw, r, hint, e))
    {
      out.push_back(e);
      return;
    }
    for (int n : M.BoundaryAdjacency(hint))
    {
      if (n >= 0 && Test(w, pw, r, n, e))
      {
        out.push_back(e);
        hint = n;
        return;
      }
    }
  }
  ++c.entrySearches;
  // A bucket's faces are first checked against the pixel by their screen box (one pixel of
  // slack, as the buckets): most of them miss it, and the exact test costs ten times more.
  const float fx = static_cast<float>(px), fy = static_cast<float>(py);
  auto scan = [&](const int* f, const int* end, bool boxed) {
    for (; f != end; ++f)
    {
      if (boxed)
      {
        const auto& b = Box[*f];
        if (fx < b[0] || fx > b[1] || fy < b[2] || fy > b[3])
        {
          continue;
        }
      }
      if (Test(w, pw, r, *f, e))
      {
        out.push_back(e);
        if (!all)
        {
          return true;
        }
      }
    }
    return false;
  };
  bool done = false;
  if (Bucketed && px >= 0 && py >= 0 && px < W && py < H)
  {
    const int k = (py / B) * BW + px / B;
    done = scan(Faces.data() + Start[k], Faces.data() + Start[k + 1], true);
  }
  if (!done)
  {
    scan(Global.data(), Global.data() + Global.size(), false);
  }
  if (all)
  {
    std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.x.t < b.x.t; });
  }
  if (!out.empty())
  {
    hint = out.front().face;
  }
}
} // namespace art
