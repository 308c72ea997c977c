// RayTrace.inl: TetRayCaster's per-ray loop (Grosso, Luerig & Ertl 1997, sec. 5): each pixel's
// ray, its entry faces, the walk through every piece it enters and its colour. TetRayCaster.cxx
// includes it twice, in namespace trace_portable and, built for AVX2, in trace_avx2
// (ART_TRACE_AVX2 1: the camera's rays walk in ProjectedWalkAvx2); both give the same bits.
// No include guard, by design.

/// Walks one piece from tet t entered through face f (the projected walk's AVX2 form when built so).
template <class Walker, class Visit>
ART_ALWAYS_INLINE inline void WalkPiece(const FrameContext& fc, const Walker& walker, int t, int f, FaceCrossing in,
  Visit& visit, FaceCrossing& out, Counters& c, std::uint64_t& nudges)
{
#if ART_TRACE_AVX2
  if constexpr (std::is_same_v<Walker, ProjectedWalker>)
  {
    WalkProjectedAvx2(fc.M, walker, t, f, in, visit, out, c.tetsCrossed, nudges, fc.records);
    return;
  }
#endif
  walker.Walk(t, f, in, visit, out, c.tetsCrossed, nudges, fc.records);
}

/// The ray starts inside tet `start` (a camera inside the mesh): from its origin to the face it
/// leaves through, then on through the neighbours like any other piece. Returns the exit's t
/// (-1e300 when the ray could not be placed: the boundary entries take over).
template <class Walker, class Visit>
ART_ALWAYS_INLINE inline double TraceFromEye(const FrameContext& fc, const TetWalker& w, const Walker& walker,
  const Ray& r, int start, Visit& visit, RayResult& res, Counters& c, std::uint64_t& nudges)
{
  FaceCrossing in, ex;
  in.t = r.tmin;
  in.s = fc.M.Evaluate(start, r.At(r.tmin));
  // An origin on a face of its tet (an eye at round coordinates in a regular grid) leaves through
  // that face at t ~ tmin, a few ulps either side: a crossing within the margin is the exit, at
  // tmin, not a face behind the ray.
  const double tMargin = 1e-9 * fc.M.Bounds().Diagonal() / Length(r.dir);
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
  const int link = fc.records[start].link[f];
  if (visit(start, in, ex) && link >= 0)
  {
    WalkPiece(fc, walker, TetMesh::LinkTet(link), TetMesh::LinkFace(link), ex, visit, out, c, nudges);
  }
  return out.t;
}

/// Every piece the ray enters through the entry faces, in t order, until the walk stops it.
template <class Walker, class Visit>
ART_ALWAYS_INLINE inline void TracePieces(const FrameContext& fc, const Walker& walker, const Ray& r, double tDone,
  EntryCursor& entries, Visit& visit, RayResult& res, Counters& c, std::uint64_t& nudges)
{
  const double tMargin = 1e-9 * fc.M.Bounds().Diagonal() / Length(r.dir);
  for (const Entry* next; !visit.Stopped() && (next = entries.Front()) != nullptr;)
  {
    const Entry e = *next;
    entries.Pop();
    if (e.x.t >= r.tmax)
    {
      break;
    }
    // An entry before the last piece's exit lies inside that piece (a duplicate at an edge). One
    // at the exit itself is the next piece behind a coincident face (whose t, from other vertex
    // ids, may differ in the last bits), so the test leaves it a margin: 1e-9 of the mesh's size,
    // in the ray's t.
    if (e.x.t < tDone - tMargin)
    {
      continue;
    }
    ++res.pieces;
    const auto& bf = fc.faces[e.face];
    FaceCrossing out;
    WalkPiece(fc, walker, bf[0], bf[1], e.x, visit, out, c, nudges);
    tDone = out.t;
  }
}

/// The ray's colour: the composite, or the transfer function at the largest scalar (a piece that
/// lay wholly before the ray's origin saw no scalar).
template <CompositeMode Mode>
ART_ALWAYS_INLINE inline void FinishRay(const RenderSettings& S, const RayAccum& acc, RayResult& res)
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

/// Integrates one ray over every piece of the mesh it passes through, front to back. w tests
/// faces (the start tet's exit); walker walks (w itself, or a ProjectedWalker for the same ray).
template <class Rule, CompositeMode Mode, class Walker>
ART_ALWAYS_INLINE inline void TraceRay(const FrameContext& fc, const Rule& rule, const TetWalker& w,
  const Walker& walker, const Ray& r, int start, EntryCursor& entries, RayResult& res, Counters& c,
  std::uint64_t& nudges, double from)
{
  SegmentCompositor<Rule, Mode> visit(fc.M, fc.S, rule, r, from, res);
  double tDone = -1e300;
  if (start >= 0 && fc.shown && !(*fc.shown)[start])
  {
    start = -1; // the eye's tet shows nothing: the region's entries take over
  }
  if (start >= 0)
  {
    tDone = TraceFromEye(fc, w, walker, r, start, visit, res, c, nudges);
  }
  if (!visit.Stopped())
  {
    TracePieces(fc, walker, r, tDone, entries, visit, res, c, nudges);
  }
  FinishRay<Mode>(fc.S, visit.Accumulated(), res);
}

/// TraceRay in the settings' mode.
template <class Rule, class Walker>
inline void Trace(const FrameContext& fc, const Rule& rule, const TetWalker& w, const Walker& walker, const Ray& r,
  int start, EntryCursor& entries, RayResult& res, Counters& c, std::uint64_t& nudges, double from)
{
  if (fc.S.mode == RenderSettings::Mode::MaxIntensity)
  {
    TraceRay<Rule, CompositeMode::Maximum>(fc, rule, w, walker, r, start, entries, res, c, nudges, from);
  }
  else if (!fc.S.isos.empty() || fc.S.shading.on)
  {
    TraceRay<Rule, CompositeMode::VolumeLit>(fc, rule, w, walker, r, start, entries, res, c, nudges, from);
  }
  else
  {
    TraceRay<Rule, CompositeMode::Volume>(fc, rule, w, walker, r, start, entries, res, c, nudges, from);
  }
}

/// The rays of one image tile, scan lines in alternating directions (each ray starts next to the
/// previous one, whose entry face the next tries first).
template <class Rule>
void RenderTile(const FrameContext& fc, const Rule& rule, const Tile& tile, Counters& c, std::uint64_t& nudges)
{
  const Camera& cam = fc.cam;
  EntryCursor entries;
  int hint = -1;
  for (int y = tile.y0; y < tile.y1; ++y)
  {
    const bool back = ((y - tile.y0) & 1) != 0;
    for (int i = tile.x0; i < tile.x1; ++i)
    {
      const int x = back ? tile.x1 - 1 - (i - tile.x0) : i;
      ++c.rays;
      ART_LEAVE_AVX();
      Ray r = cam.Generate(x, y);
      if (fc.ends)
      {
        r.tmax = (*fc.ends)[static_cast<std::size_t>(y) * cam.Width() + x];
      }
      double from;
      if (!TetRayCaster::Impl::StartRay(fc, r, from))
      {
        continue;
      }
      const TetWalker w(fc.M, r);
      std::optional<ProjectedWalker> pw;
      if (fc.view && fc.view->Fits(r))
      {
        pw.emplace(*fc.view, r);
      }
      ART_LEAVE_AVX();
      TetRayCaster::Impl::Entries(fc, w, r, x, y, entries, hint, c, pw ? &*pw : nullptr);
      if (!entries.Front() && fc.eyeTet < 0)
      {
        continue;
      }
      ++c.hits;
      RayResult res;
      if (pw)
      {
        Trace(fc, rule, w, *pw, r, fc.eyeTet, entries, res, c, nudges, from);
      }
      else
      {
        Trace(fc, rule, w, w, r, fc.eyeTet, entries, res, c, nudges, from);
      }
      const std::array<float, 4> rgba{ float(res.rgba[0]), float(res.rgba[1]), float(res.rgba[2]), float(res.rgba[3]) };
      ART_LEAVE_AVX();
      fc.img.Set(x, y, rgba);
    }
  }
}
