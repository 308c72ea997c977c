#include "TetRayCaster.h"

#include "EntryFinder.h"
#include "Error.h"
#include "ExactIntegrator.h"
#include "MeanSpacing.h"
#include "ParallelTiles.h"
#include "Progress.h"
#include "ProjectedWalkAvx2.h"
#include "ProjectedWalker.h"
#include "SegmentCompositor.h"
#include "TetWalker.h"
#include "Accelerator.h"
#include "TriangleStore.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#if defined(__GNUC__)
#define ART_ALWAYS_INLINE __attribute__((always_inline))
#else
#define ART_ALWAYS_INLINE
#endif

namespace art
{
/// What the rays of one frame share.
struct FrameContext
{
  const TetRayCaster& rc;
  const TetMesh& M;
  const RenderSettings& S;
  const Camera& cam;
  const EntryFinder& finder;
  const ProjectedView* view;        ///< null: every ray walks in 3-D
  const std::vector<double>* ends;  ///< each pixel's ray end, or null
  bool region;                      ///< rays enter the shown region (empty-space skipping)
  const TetRecord* records;         ///< the table walked: the mesh's, or the region's
  const std::vector<std::array<int, 2>>& faces; ///< the faces entered through
  const std::vector<char>* shown;   ///< the region's tets (null without one)
  int eyeTet;                       ///< the tet holding a perspective eye, or -1
  Image& img;
};

struct TetRayCaster::Impl
{
  /// The entry faces of ray r through pixel px, py (entry search): for a convex mesh the one face,
  /// from the previous ray's (hint) or the screen buckets; else every one in t order, from the
  /// screen buckets (a region, or without the boundary grid) or the boundary grid's voxels.
  static void Entries(const FrameContext& fc, const TetWalker& w, const Ray& r, int px, int py, EntryCursor& out,
    int& hint, Counters& c, const ProjectedWalker* pw)
  {
    Entries(fc.rc, fc.finder, w, r, px, py, out, hint, c, fc.region, pw);
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

  /// Ray r of the frame made ready to trace: false when it misses the mesh or its clipped part.
  /// A parallel camera's rays starting inside the box are traced from where their line enters it
  /// and integrated from their origins on (`from`): no walk has to find the tet holding each
  /// origin (in a non-convex mesh, that walk can leave through a hole and miss it); a
  /// perspective eye inside the mesh starts in its tet (FrameContext::eyeTet).
  static bool StartRay(const FrameContext& fc, Ray& r, double& from)
  {
    from = -std::numeric_limits<double>::infinity();
    double t0, t1;
    if (!fc.M.Bounds().Clip(r, t0, t1))
    {
      return false;
    }
    if (fc.cam.IsParallel() && fc.M.Bounds().Contains(r.At(r.tmin)))
    {
      Ray line = r;
      line.tmin = -std::numeric_limits<double>::infinity();
      double l0, l1;
      fc.M.Bounds().Clip(line, l0, l1);
      from = r.tmin;
      r.tmin = std::min(l0, r.tmin) - 1e-6 * (l1 - l0); // the box's faces a margin inside
    }
    return CutByPlanes(fc.S.clipPlanes, r, t0, t1, from);
  }

  template <class Rule>
  static RenderStats RenderWith(const TetRayCaster& rc, const Rule& rule, const Camera& cam, Image& img, Progress* p,
    const std::vector<double>* ends);
};

// The per-ray loop, twice: portable, and built for AVX2 with the projected walk in its SIMD form
// (chosen per frame when the CPU has AVX2). Functions from elsewhere that it inlines are built
// for the loop they land in; those it calls stay portable.
namespace trace_portable
{
#define ART_TRACE_AVX2 0
#define ART_LEAVE_AVX() (void)0
#include "RayTrace.inl"
#undef ART_LEAVE_AVX
#undef ART_TRACE_AVX2
} // namespace trace_portable
#ifdef ART_HAVE_AVX2_WALK
#pragma GCC push_options
#pragma GCC target("avx2")
namespace trace_avx2
{
// The AVX2 loop calls portable code for each ray (the camera, the entry search, the image). GCC
// marks no 256-bit register in use there, so it clears none, yet the processor still counts the
// upper halves as in use and every SSE instruction of the callee pays for it (the AVX-SSE
// transition, which cost more than the calls themselves): they are cleared first.
#define ART_TRACE_AVX2 1
#define ART_LEAVE_AVX() _mm256_zeroupper()
#include "RayTrace.inl"
#undef ART_LEAVE_AVX
#undef ART_TRACE_AVX2
} // namespace trace_avx2
#pragma GCC pop_options
#endif

bool SimdWalkAvailable()
{
#ifdef ART_HAVE_AVX2_WALK
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}

template <class Rule>
RenderStats TetRayCaster::Impl::RenderWith(const TetRayCaster& rc, const Rule& rule, const Camera& cam, Image& img,
  Progress* p, const std::vector<double>* ends)
{
  const auto start = std::chrono::steady_clock::now();
  img = Image(cam.Width(), cam.Height());
  bool region = rc.Shown.on;
  auto finder = std::make_unique<const EntryFinder>(rc.M, cam, region ? &rc.Shown.faces : nullptr);
  if (region && finder->GlobalCount() > 256)
  {
    // An eye inside the shown region's surface leaves the faces across its plane to every ray:
    // past a few hundred, walking every tet costs less.
    region = false;
    finder = std::make_unique<const EntryFinder>(rc.M, cam);
  }
  const bool parallel = cam.IsParallel();
  const int eyeTet = !parallel && rc.M.Bounds().Contains(cam.Position()) ? rc.M.Locate(cam.Position()) : -1;
  std::unique_ptr<const ProjectedView> view;
  if (rc.S.projectedWalk)
  {
    view = std::make_unique<const ProjectedView>(rc.M, cam);
  }
  const FrameContext fc{ rc, rc.M, rc.S, cam, *finder, view ? view.get() : nullptr, ends, region,
    region ? rc.Shown.records.data() : rc.M.Records(), region ? rc.Shown.faces : rc.M.BoundaryFaces(),
    region ? &rc.Shown.shown : nullptr, eyeTet, img };
  const bool simd = rc.S.simdWalk && SimdWalkAvailable();
  if (p)
  {
    p->Begin("render", double(cam.Width()) * cam.Height()); // ForEachTile counts pixels
  }
  std::atomic<std::uint64_t> nudges{ 0 };
  RenderStats st;
  st.counters = ForEachTile(cam.Width(), cam.Height(), rc.S.tileSize,
    [&](const Tile& tile, Counters& c) {
      // A tile no face projects onto keeps the background: its rays are not even made (most of a
      // frame around a head; rays from inside the mesh start in the eye's tet).
      if (eyeTet < 0 && finder->Empty(tile.x0, tile.y0, tile.x1, tile.y1))
      {
        c.rays += static_cast<std::uint64_t>(tile.x1 - tile.x0) * (tile.y1 - tile.y0);
        return;
      }
      std::uint64_t nd = 0;
#ifdef ART_HAVE_AVX2_WALK
      if (simd)
      {
        trace_avx2::RenderTile(fc, rule, tile, c, nd);
      }
      else
#endif
      {
        trace_portable::RenderTile(fc, rule, tile, c, nd);
      }
      nudges += nd;
    },
    p);
  st.nudges = nudges;
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return st;
}

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
  const Camera none;
  Image img;
  const FrameContext fc{ *this, M, S, none, finder, nullptr, nullptr, false, M.Records(), M.BoundaryFaces(), nullptr,
    start, img };
  if (S.rule == RenderSettings::Rule::Trapezoid)
  {
    trace_portable::Trace(fc, TrapezoidRule(S.tf), w, w, r, start, entries, res, c, nudges, from);
  }
  else
  {
    trace_portable::Trace(fc, ExactIntegrator(S.tf), w, w, r, start, entries, res, c, nudges, from);
  }
  return res;
}
} // namespace art
