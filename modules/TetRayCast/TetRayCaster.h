// TetRayCaster: cell-by-cell ray casting of a tetrahedral grid (Grosso, Luerig & Ertl 1997, sec. 5):
// entry face per ray (EntryFinder), face-to-face traversal (TetWalker; ProjectedWalker for a
// camera's rays), emission-absorption per segment with the exact or the trapezoid rule
// (ExactIntegrator), iso-surfaces with Phong-shaded interpolated vertex gradients, maximum
// intensity, early ray termination, empty-space skipping (only tets the transfer function can
// show are walked). Non-convex meshes are integrated over every piece the ray passes through.
// Image tiles run over art::ForEachTile, so the image is identical for any thread count.
#ifndef art_TetRayCaster_h
#define art_TetRayCaster_h

#include "AdaptiveRTTetRayCastModule.h"
#include "Camera.h"
#include "Counters.h"
#include "Image.h"
#include "IsoSurfaceHit.h"
#include "TetMesh.h"
#include "TransferFunction.h"

#include <array>
#include <memory>
#include <vector>

namespace art
{
class Accelerator;
class Progress;

struct RenderSettings
{
  enum class Mode
  {
    Composite,   ///< emission-absorption (plus iso-surfaces)
    MaxIntensity ///< colour and opacity of the largest scalar on the ray
  };
  enum class Rule
  {
    Exact,    ///< split at control points, closed form per piece
    Trapezoid ///< the seed paper's rule
  };
  TransferFunction tf;
  Mode mode = Mode::Composite;
  Rule rule = Rule::Exact;
  double earlyTermination = 0.99; ///< stop when opacity reaches this (>= 1: never)
  std::vector<IsoSurface> isos;
  double ambient = 0.3, diffuse = 0.7; ///< headlight shading of iso-surfaces
  /// Shading of the volume itself (vtkVolumeProperty::ShadeOn): a headlight, two-sided, through
  /// each tet's gradient, Blinn-Phong with VTK's coefficients (and its defaults).
  struct Shading
  {
    bool on = false;
    double ambient = 0.1, diffuse = 0.7, specular = 0.2, power = 10.0;
  } shading;
  int tileSize = 16;
  /// Non-convex meshes: entry faces from the boundary triangles in the TriangleGrid's voxels along
  /// the ray (true) or from testing every face in the pixel's screen bucket (false).
  bool boundaryGrid = true;
  /// Walk the camera's rays in its projection (ProjectedWalker: 2-D side products) where it is
  /// valid, or always with the 3-D TetWalker (false).
  bool projectedWalk = true;
  /// Walk the camera's rays with the SIMD form of the projected walk where the CPU has AVX2
  /// (the same image bit for bit; false: the portable form).
  bool simdWalk = true;
  /// Empty-space skipping (composite mode): walk only the tets the transfer function or an
  /// iso-surface can show anywhere between their vertex scalars. Rays enter that region through
  /// its boundary faces (screen buckets, every entry) and leave it where it ends. The image is
  /// the same up to round-off: the skipped tets add nothing.
  bool skipEmpty = true;
  /// Clipping planes (a, b, c, d) in the mesh's coordinates: only where a x + b y + c z + d >= 0
  /// is drawn (the side the normal points to, as VTK's mappers keep). Each ray's interval is cut,
  /// so moving a plane costs nothing; the image is that of the mesh cut by the planes (the field
  /// is linear in each tet).
  std::vector<std::array<double, 4>> clipPlanes;
  /// Also leave the tets wholly on a plane's clipped side out of the walk (with skipEmpty): rays
  /// then enter at the cut instead of walking the clipped part, for the cost of rebuilding the
  /// walked region whenever the planes change (~35 ns per tet). A mapper turns it off while a
  /// plane moves. The image is the same either way.
  bool cullClipped = true;
};

/// True when this CPU runs the SIMD form of the projected walk (RenderSettings::simdWalk).
ADAPTIVERTTETRAYCAST_EXPORT bool SimdWalkAvailable();

/// Cuts [t0, t1] of ray r to where every plane (a, b, c, d) has a x + b y + c z + d >= 0.
/// Returns false when nothing is left.
ADAPTIVERTTETRAYCAST_EXPORT bool ClipToPlanes(
  const std::vector<std::array<double, 4>>& planes, const Ray& r, double& t0, double& t1);

struct RayResult
{
  double rgba[4] = { 0, 0, 0, 0 }; ///< premultiplied colour, opacity
  double firstIso = -1;            ///< t of the first iso-surface hit, -1 for none
  double maxScalar = -1e300;
  int pieces = 0;                  ///< times the ray entered the mesh
};

struct RenderStats
{
  Counters counters;
  double seconds = 0;
  std::uint64_t nudges = 0; ///< fallback exits (rays in face planes)
};

class ADAPTIVERTTETRAYCAST_EXPORT TetRayCaster
{
public:
  /// Keeps a reference to `mesh`, which must outlive the caster. A non-convex mesh gets its
  /// boundary faces put into a TriangleGrid (recursive grid) here.
  TetRayCaster(const TetMesh& mesh, RenderSettings settings);
  ~TetRayCaster();

  /// Renders cam's view into img (resized to the camera): premultiplied RGBA, not composited.
  /// `ends` (width x height, row 0 at the top) gives each pixel's ray a far end, in the t of
  /// cam.Generate's ray: opaque geometry in the scene, which the volume behind it must not show
  /// through. Infinity for none.
  RenderStats Render(const Camera& cam, Image& img, Progress* progress = nullptr,
    const std::vector<double>* ends = nullptr) const;
  /// One ray on its own (tests every boundary face for the entry: for checks, not for speed).
  /// The ray's tmax ends it, as `ends` does in Render.
  RayResult Cast(const Ray& r) const;

  /// New settings for the next Render (transfer function, iso-surfaces, ...), keeping what was
  /// built for the mesh (the boundary grid of a non-convex mesh).
  void SetSettings(RenderSettings settings);
  const RenderSettings& Settings() const { return S; }
  const TetMesh& Mesh() const { return M; }

  struct Impl;

private:
  const TetMesh& M;
  RenderSettings S;
  std::unique_ptr<const Accelerator> Boundary; ///< boundary triangles of a non-convex mesh
  Vec3 BoundaryOrigin;                          ///< where Boundary's coordinates are taken from
  /// Empty-space skipping (RenderSettings::skipEmpty): which tets can show, the records with links
  /// into the others cut, and the faces through which rays enter the shown region.
  struct Region
  {
    bool on = false;
    std::vector<char> shown;
    std::vector<TetRecord> records; ///< the mesh's records, links into the others cut
    std::vector<std::array<int, 2>> faces;
    std::vector<double> key; ///< what it was built for: opacity nodes and iso values
    bool built = false;
  } Shown;
  void BuildRegion();
};
} // namespace art

#endif
