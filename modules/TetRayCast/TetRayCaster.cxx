#include "TetRayCaster.h"

#include "EntryFinder.h"
#include "Error.h"
#include "ExactIntegrator.h"
#include "MeanSpacing.h"
#include "ParallelTiles.h"
#include "Progress.h"
#include "ProjectedWalker.h"
#include "SegmentCompositor.h"
#include "TetWalker.h"
#include "Accelerator.h"
#include "TriangleStore.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#if defined(__GNUC__)
#define ART_ALWAYS_INLINE __attribute__((always_inline))
#else
#define ART_ALWAYS_INLINE
#endif

namespace art
{
struct TetRayCaster::Impl
{
  /// Integrates one ray over every piece of the mesh it passes through, front to back. w tests
  /// faces (the start tet's exit); walker walks (w itself, or a ProjectedWalker for the same ray).
  /// With `region`, the entries are the shown region's faces and the walk stops where it does.
  template <class Rule, CompositeMode Mode, class Walker>
  static void TraceRay(const TetRayCaster& rc, const Rule& rule, const TetWalker& w, const Walker& walker,
    const Ray& r, int start, EntryCursor& entries, RayResult& res, Counters& c, std::uint64_t& nudges,
    bool region, double from)
  {
    const TetRecord* records = region ? rc.Shown.records.data() : rc.M.Records();
    SegmentCompositor<Rule, Mode> visit(rc.M, rc.S, rule, r, from, res);
    double tDone = -1e300;
    if (start >= 0 && region && !rc.Shown.shown[start])
    {
      start = -1; // the eye's tet shows nothing: the region's entries take over
    }
    if (start >= 0)
    {
      tDone = TraceFromEye(rc, w, walker, r, start, records, visit, res, c, nudges);
    }
    if (!visit.Stopped())
    {
      TracePieces(rc, walker, r, tDone, region, records, entries, visit, res, c, nudges);
    }
    FinishRay<Mode>(rc.S, visit.Accumulated(), res);
  }

  /// The ray starts inside tet `start` (a camera inside the mesh): from its origin to the face it
  /// leaves through, then on through the neighbours like any other piece. Returns the exit's t
  /// (-1e300 when the ray could not be placed: the boundary entries take over).
  template <class Walker, class Visit>
  static double TraceFromEye(const TetRayCaster& rc, const TetWalker& w, const Walker& walker, const Ray& r,
    int start, const TetRecord* records, Visit& visit, RayResult& res, Counters& c, std::uint64_t& nudges)
  {
    const TetMesh& M = rc.M;
    FaceCrossing in, ex;
    in.t = r.tmin;
    in.s = M.Evaluate(start, r.At(r.tmin));
    // An origin on a face of its tet (an eye at round coordinates in a regular grid) leaves
    // through that face at t ~ tmin, a few ulps either side: a crossing within the margin is the
    // exit, at tmin, not a face behind the ray.
    const double tMargin = 1e-9 * M.Bounds().Diagonal() / Length(r.dir);
    int f = -1;
    for (int k = 0; k < 4 && f < 0; ++k)
    {
      if (w.Crosses(start, k, +1, ex) && ex.t >= in.t - tMargin)
      {
        f = k;
        ex.t = std::max(ex.t, in.t);
      }
    }
    if (f < 0)
    {
      ++nudges; // the origin on a face or the ray in one
      return -1e300;
    }
    ++res.pieces;
    ++c.tetsCrossed;
    FaceCrossing out = ex;
    const int link = records[start].link[f];
    if (visit(start, in, ex) && link >= 0)
    {
      walker.Walk(TetMesh::LinkTet(link), TetMesh::LinkFace(link), ex, visit, out, c.tetsCrossed, nudges, records);
    }
    return out.t;
  }

  /// Every piece the ray enters through the entry faces, in t order, until the walk stops it.
  template <class Walker, class Visit>
  static void TracePieces(const TetRayCaster& rc, const Walker& walker, const Ray& r, double tDone, bool region,
    const TetRecord* records, EntryCursor& entries, Visit& visit, RayResult& res, Counters& c,
    std::uint64_t& nudges)
  {
    const auto& faces = region ? rc.Shown.faces : rc.M.BoundaryFaces();
    const double tMargin = 1e-9 * rc.M.Bounds().Diagonal() / Length(r.dir);
    for (const Entry* next; !visit.Stopped() && (next = entries.Front()) != nullptr;)
    {
      const Entry e = *next;
      entries.Pop();
      if (e.x.t >= r.tmax)
      {
        break;
      }
      // An entry before the last piece's exit lies inside that piece (a duplicate at an edge).
      // One at the exit itself is the next piece behind a coincident face (whose t, from other
      // vertex ids, may differ in the last bits), so the test leaves it a margin: 1e-9 of the
      // mesh's size, in the ray's t.
      if (e.x.t < tDone - tMargin)
      {
        continue;
      }
      ++res.pieces;
      const auto& bf = faces[e.face];
      FaceCrossing out;
      walker.Walk(bf[0], bf[1], e.x, visit, out, c.tetsCrossed, nudges, records);
      tDone = out.t;
    }
  }

  /// The ray's colour: the composite, or the transfer function at the largest scalar (a piece
  /// that lay wholly before the ray's origin saw no scalar).
  template <CompositeMode Mode>
  static void FinishRay(const RenderSettings& S, const RayAccum& acc, RayResult& res)
  {
    if constexpr (Mode == CompositeMode::Maximum)
    {
      if (res.pieces > 0 && res.maxScalar > -1e300)
      {
        double rgb[3], tau;
        S.tf.Evaluate(res.maxScalar, rgb, tau);
        const double a = S.tf.Alpha(res.maxScalar);
        res.rgba[0] = rgb[0] * a, res.rgba[1] = rgb[1] * a, res.rgba[2] = rgb[2] * a, res.rgba[3] = a;
      }
    }
    else
    {
      res.rgba[0] = acc.rgb[0], res.rgba[1] = acc.rgb[1], res.rgba[2] = acc.rgb[2], res.rgba[3] = acc.Alpha();
    }
  }

  /// TraceRay in the settings' mode.
  template <class Rule, class Walker>
  static void Trace(const TetRayCaster& rc, const Rule& rule, const TetWalker& w, const Walker& walker,
    const Ray& r, int start, EntryCursor& entries, RayResult& res, Counters& c, std::uint64_t& nudges,
    bool region = false, double from = -std::numeric_limits<double>::infinity())
  {
    if (rc.S.mode == RenderSettings::Mode::MaxIntensity)
    {
      TraceRay<Rule, CompositeMode::Maximum>(rc, rule, w, walker, r, start, entries, res, c, nudges, region, from);
    }
    else if (!rc.S.isos.empty())
    {
      TraceRay<Rule, CompositeMode::VolumeIsos>(rc, rule, w, walker, r, start, entries, res, c, nudges, region, from);
    }
    else
    {
      TraceRay<Rule, CompositeMode::Volume>(rc, rule, w, walker, r, start, entries, res, c, nudges, region, from);
    }
  }

  static void Entries(const TetRayCaster& rc, const EntryFinder& f, const TetWalker& w, const Ray& r,
    int px, int py, EntryCursor& out, int& hint, Counters& c, bool region = false,
    const ProjectedWalker* pw = nullptr)
  {
    const bool convex = rc.M.IsConvex();
    if (convex && !region)
    {
      f.Find(w, r, px, py, false, out.List(), hint, c, pw);
      return;
    }
    if (region || !rc.Boundary || !rc.S.boundaryGrid)
    {
      f.Start(out, w, r, px, py, c, pw);
      return;
    }
    // Non-convex: every boundary face in the TriangleGrid's voxels along the ray gets the exact
    // Pluecker test, sorted by t. Not the grid's own all-hits query: that merges hits at one t
    // into one surface, so of two coincident faces (the exit of one piece and the entry of the
    // next, as in a mesh whose tets keep their own points) only one would be tried.
    thread_local std::vector<long long> cand;
    Ray local = r;
    local.org = r.org - rc.BoundaryOrigin;
    rc.Boundary->Candidates(local, cand, c);
    auto& list = out.List();
    list.clear();
    const auto& bfs = rc.M.BoundaryFaces();
    for (long long b : cand)
    {
      Entry e;
      if (w.Crosses(bfs[b][0], bfs[b][1], -1, e.x) && e.x.t >= r.tmin)
      {
        e.face = static_cast<int>(b);
        list.push_back(e);
      }
    }
    std::stable_sort(list.begin(), list.end(), [](const Entry& a, const Entry& b) { return a.x.t < b.x.t; });
  }

  // The clipping planes' interval of ray r (box interval [t0, t1]): the walk still starts at the
  // mesh's surface, nothing before the interval is integrated (`from`) and the ray ends where it
  // does (r.tmax). False when nothing of it is left inside the box.
  static bool CutByPlanes(const std::vector<std::array<double, 4>>& planes, Ray& r, double t0, double t1, double& from)
  {
    if (planes.empty())
    {
      return true;
    }
    double c0 = r.tmin, c1 = r.tmax;
    if (!ClipToPlanes(planes, r, c0, c1) || !(std::max(c0, t0) < std::min(c1, t1)))
    {
      return false;
    }
    from = std::max(from, c0);
    r.tmax = c1;
    return true;
  }

  template <class Rule>
  static RenderStats RenderWith(const TetRayCaster& rc, const Rule& rule, const Camera& cam, Image& img, Progress* p,
    const std::vector<double>* ends)
  {
    const auto start = std::chrono::steady_clock::now();
    img = Image(cam.Width(), cam.Height());
    bool region = rc.Shown.on;
    auto finder = std::make_unique<const EntryFinder>(rc.M, cam, region ? &rc.Shown.faces : nullptr);
    if (region && finder->GlobalCount() > 256)
    {
      // An eye inside the shown region's surface leaves the faces across its plane to every
      // ray: past a few hundred, walking every tet costs less.
      region = false;
      finder = std::make_unique<const EntryFinder>(rc.M, cam);
    }
    const bool parallel = cam.IsParallel();
    const int eyeTet = !parallel && rc.M.Bounds().Contains(cam.Position()) ? rc.M.Locate(cam.Position()) : -1;
    std::atomic<std::uint64_t> nudges{ 0 };
    std::unique_ptr<const ProjectedView> view;
    if (rc.S.projectedWalk)
    {
      view = std::make_unique<const ProjectedView>(rc.M, cam);
    }
    if (p)
    {
      p->Begin("render", double(cam.Width()) * cam.Height()); // ForEachTile counts pixels
    }
    RenderStats st;
    st.counters = ForEachTile(cam.Width(), cam.Height(), rc.S.tileSize,
      [&](const Tile& tile, Counters& c) {
        // A tile no face projects onto keeps the background: its rays are not even made (most
        // of a frame around a head; rays from inside the mesh start in the eye's tet).
        if (eyeTet < 0 && finder->Empty(tile.x0, tile.y0, tile.x1, tile.y1))
        {
          c.rays += static_cast<std::uint64_t>(tile.x1 - tile.x0) * (tile.y1 - tile.y0);
          return;
        }
        EntryCursor entries;
        std::uint64_t nd = 0;
        int hint = -1;
        for (int y = tile.y0; y < tile.y1; ++y)
        {
          // Scan lines in alternating directions: each ray starts next to the previous one.
          const bool back = ((y - tile.y0) & 1) != 0;
          for (int i = tile.x0; i < tile.x1; ++i)
          {
            const int x = back ? tile.x1 - 1 - (i - tile.x0) : i;
            ++c.rays;
            Ray r = cam.Generate(x, y);
            if (ends)
            {
              r.tmax = (*ends)[static_cast<std::size_t>(y) * cam.Width() + x];
            }
            double t0, t1;
            if (!rc.M.Bounds().Clip(r, t0, t1))
            {
              continue;
            }
            // A ray from inside the mesh starts in the tet holding its origin: the eye's for a
            // perspective camera. A parallel camera's rays starting inside the box are traced
            // from where their line enters it and integrated from their origins on: no walk has
            // to find the tet holding each origin (in a non-convex mesh, that walk can leave
            // through a hole and miss it).
            const int start = eyeTet;
            double from = -std::numeric_limits<double>::infinity();
            if (parallel && rc.M.Bounds().Contains(r.At(r.tmin)))
            {
              Ray line = r;
              line.tmin = -std::numeric_limits<double>::infinity();
              double l0, l1;
              rc.M.Bounds().Clip(line, l0, l1);
              from = r.tmin;
              r.tmin = std::min(l0, r.tmin) - 1e-6 * (l1 - l0); // the box's faces a margin inside
            }
            if (!CutByPlanes(rc.S.clipPlanes, r, t0, t1, from))
            {
              continue;
            }
            const TetWalker w(rc.M, r);
            std::optional<ProjectedWalker> pw;
            if (view && view->Fits(r))
            {
              pw.emplace(*view, r);
            }
            Entries(rc, *finder, w, r, x, y, entries, hint, c, region, pw ? &*pw : nullptr);
            if (!entries.Front() && start < 0)
            {
              continue;
            }
            ++c.hits;
            RayResult res;
            if (pw)
            {
              Trace(rc, rule, w, *pw, r, start, entries, res, c, nd, region, from);
            }
            else
            {
              Trace(rc, rule, w, w, r, start, entries, res, c, nd, region, from);
            }
            img.Set(x, y, { float(res.rgba[0]), float(res.rgba[1]), float(res.rgba[2]), float(res.rgba[3]) });
          }
        }
        nudges += nd;
      },
      p);
    st.nudges = nudges;
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return st;
  }
};

TetRayCaster::TetRayCaster(const TetMesh& mesh, RenderSettings settings)
  : M(mesh)
{
  SetSettings(std::move(settings));
  if (!M.IsConvex())
  {
    std::vector<std::array<long long, 3>> tris;
    tris.reserve(M.BoundaryFaces().size());
    for (const auto& bf : M.BoundaryFaces())
    {
      const auto& v = M.Tet(bf[0]);
      const int* fv = TetMesh::FaceVertex[bf[1]];
      tris.push_back({ v[fv[0]], v[fv[1]], v[fv[2]] });
    }
    // The grid stores floats: a mesh far from the origin, in survey coordinates, is taken about
    // its centre (and rays are moved alike) so its faces stay apart.
    BoundaryOrigin = TriangleStore::OriginFor(M.Bounds());
    Boundary = MakeAccelerator(std::make_shared<const TriangleStore>(M.PointsArray(), tris, BoundaryOrigin));
  }
}

TetRayCaster::~TetRayCaster() = default;

void TetRayCaster::SetSettings(RenderSettings settings)
{
  S = std::move(settings);
  if (S.tf.Nodes().empty())
  {
    const Vec3 e = M.Bounds().hi - M.Bounds().lo;
    const double extent[3] = { e.x, e.y, e.z };
    const double lo = M.ScalarRange(0), hi = M.ScalarRange(1);
    S.tf = TransferFunction::Preset("grey-ramp", lo, hi,
      TransferFunction::PresetUnitDistance(lo, hi, MeanSpacing(extent, double(M.NumberOfPoints()))));
  }
  BuildRegion();
}

RenderStats TetRayCaster::Render(const Camera& cam, Image& img, Progress* progress, const std::vector<double>* ends) const
{
  if (ends && ends->size() != static_cast<std::size_t>(cam.Width()) * cam.Height())
  {
    throw Error("TetRayCaster::Render: the ray ends do not match the camera's image size");
  }
  if (S.rule == RenderSettings::Rule::Trapezoid)
  {
    return Impl::RenderWith(*this, TrapezoidRule(S.tf), cam, img, progress, ends);
  }
  return Impl::RenderWith(*this, ExactIntegrator(S.tf), cam, img, progress, ends);
}

bool ClipToPlanes(const std::vector<std::array<double, 4>>& planes, const Ray& r, double& t0, double& t1)
{
  for (const auto& q : planes)
  {
    // a.(o + t d) + d0 >= 0  <=>  t * (a.d) >= -(a.o + d0)
    const double num = q[0] * r.org.x + q[1] * r.org.y + q[2] * r.org.z + q[3];
    const double den = q[0] * r.dir.x + q[1] * r.dir.y + q[2] * r.dir.z;
    if (den > 0)
    {
      t0 = std::max(t0, -num / den);
    }
    else if (den < 0)
    {
      t1 = std::min(t1, -num / den);
    }
    else if (num < 0)
    {
      return false; // parallel to the plane, on its clipped side
    }
  }
  return t0 < t1;
}

RayResult TetRayCaster::Cast(const Ray& ray) const
{
  RayResult res;
  double t0, t1;
  if (!ray.IsValid() || !M.Bounds().Clip(ray, t0, t1))
  {
    return res;
  }
  Ray r = ray;
  double from = -std::numeric_limits<double>::infinity();
  if (!Impl::CutByPlanes(S.clipPlanes, r, t0, t1, from))
  {
    return res;
  }
  const EntryFinder finder(M);
  const TetWalker w(M, r);
  EntryCursor entries;
  int hint = -1;
  Counters c;
  std::uint64_t nudges = 0;
  Impl::Entries(*this, finder, w, r, -1, -1, entries, hint, c);
  const int start = M.Bounds().Contains(r.At(r.tmin)) ? M.Locate(r.At(r.tmin)) : -1;
  if (S.rule == RenderSettings::Rule::Trapezoid)
  {
    Impl::Trace(*this, TrapezoidRule(S.tf), w, w, r, start, entries, res, c, nudges, false, from);
  }
  else
  {
    Impl::Trace(*this, ExactIntegrator(S.tf), w, w, r, start, entries, res, c, nudges, false, from);
  }
  return res;
}
} // namespace art
