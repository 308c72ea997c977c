// Camera: pinhole (perspective) or parallel projection, made from a vtkCamera so that the batch
// renderer and a VTK window see the same view. Pixel (0,0) is the top-left pixel, as in files.
#ifndef art_Camera_h
#define art_Camera_h

#include "AdaptiveRTCoreModule.h"
#include "Box3.h"
#include "Ray.h"

class vtkCamera;

namespace art
{
class ADAPTIVERTCORE_EXPORT Camera
{
public:
  Camera() = default;

  /// The view of `cam` for an image of width x height pixels (VTK's vertical view angle,
  /// or the horizontal one when the camera says so; parallel scale for parallel projection;
  /// the window centre, which shifts the image off the view axis as vtkRenderLargeImage's tiles do).
  static Camera FromVTK(vtkCamera* cam, int width, int height);

  /// Points `cam` at `bounds` from the given direction the way vtkRenderer::ResetCamera does,
  /// then applies azimuth and elevation (degrees) about the focal point and a zoom factor.
  /// `aspect` (image width / height) below 1 fits the narrower horizontal angle instead, so a
  /// portrait image keeps the data's sides (the vertical angle alone cut them off).
  static void Frame(vtkCamera* cam, const Box3& bounds, double azimuth = 0.0,
    double elevation = 0.0, double zoom = 1.0, double aspect = 1.0);
  /// How FrameObject fits: the object's box as this view sees it, or (Orbit) a cylinder about the
  /// view-up axis holding the box, so that every azimuth of an orbit gets the same distance.
  enum class Fit
  {
    View,
    Orbit
  };
  /// The fraction of the frame's narrower fitting side the object fills.
  static constexpr double FitFraction = 0.85;
  /// Frame, but fitted to `object` (the visible part of the data) to FitFraction of the frame,
  /// its centre at the frame's centre; the eye is kept outside `data` (the whole box the casters
  /// enter), narrowing the view angle instead when the fit would put it inside.
  static void FrameObject(vtkCamera* cam, const Box3& object, const Box3& data, double azimuth = 0.0,
    double elevation = 0.0, double zoom = 1.0, double aspect = 1.0, Fit fit = Fit::View);
  /// Degrees above the horizon the default view of a flat, wide triangle scene (a game level, a
  /// terrain, a floor plan; LayoutView) is raised by: from the front it is a thin strip.
  static constexpr double LayoutElevation = 45.0;
  /// Is a scene of `bounds` flat and wide: lower than 0.6 of its width, yet not flat in z
  /// (which DefaultView already sees from above)?
  static bool LayoutView(const Box3& bounds)
  {
    const Vec3 e = bounds.Size();
    const double wide = e.x > e.y ? e.x : e.y;
    return e.z < 0.6 * wide && e.z >= 0.05 * wide;
  }
  /// The default view direction of the CLI and the viewer, before Frame: from the front (-y), z
  /// up; flat data (thinner than 1/20 of its width in z, or in x) face on: from above with y up
  /// (ParaView's default view), or from the side. Edge on, a slab drew as a line or nothing.
  static void DefaultView(vtkCamera* cam, const Box3& bounds);

  /// The ray through the centre of pixel (px, py); fractional positions give sub-pixel rays.
  Ray Generate(double px, double py) const;

  int Width() const { return W; }
  int Height() const { return H; }
  bool IsParallel() const { return Parallel; }
  const Vec3& Position() const { return Eye; }
  const Vec3& Forward() const { return Fwd; }

private:
  Vec3 Eye, Fwd{ 0, 0, -1 }, Right{ 1, 0, 0 }, Up{ 0, 1, 0 };
  double HalfW = 1.0, HalfH = 1.0; // image-plane half extents at distance 1 (or world units)
  double Cx = 0.0, Cy = 0.0;       // vtkCamera's window centre: the image's centre, in half extents
  int W = 1, H = 1;
  bool Parallel = false;
};
} // namespace art

#endif
