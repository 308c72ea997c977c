#include "Camera.h"
#include "Error.h"

#include <vtkCamera.h>
#include <vtkMath.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace art
{
Camera Camera::FromVTK(vtkCamera* cam, int width, int height)
{
  Camera c;
  c.W = std::max(1, width);
  c.H = std::max(1, height);
  c.Eye = Vec3(cam->GetPosition());
  const Vec3 focal(cam->GetFocalPoint());
  c.Fwd = Normalize(focal - c.Eye);
  c.Right = Normalize(Cross(c.Fwd, Vec3(cam->GetViewUp())));
  c.Up = Cross(c.Right, c.Fwd);
  c.Parallel = cam->GetParallelProjection() != 0;
  const double aspect = double(c.W) / double(c.H);
  // SetWindowCenter moves the frustum's window across the image plane ((centre - 1, centre + 1)
  // half extents each way): vtkRenderLargeImage renders each tile of a large screenshot so.
  const double* centre = cam->GetWindowCenter();
  c.Cx = centre[0];
  c.Cy = centre[1];
  if (c.Parallel)
  {
    c.HalfH = cam->GetParallelScale();
    c.HalfW = c.HalfH * aspect;
  }
  else
  {
    const double half = std::tan(vtkMath::RadiansFromDegrees(cam->GetViewAngle()) * 0.5);
    if (cam->GetUseHorizontalViewAngle())
    {
      c.HalfW = half;
      c.HalfH = half / aspect;
    }
    else
    {
      c.HalfH = half;
      c.HalfW = half * aspect;
    }
    // VTK shears a perspective projection about a plane at distance zp (vtkPerspectiveTransform::
    // Shear: x' = x - dxdz (z + zp) in eye coordinates) for each eye of a stereo render (half the
    // eye angle, negative for the left eye, about the focal plane) and for SetViewShear; the two
    // compose into one shear. Its rays leave an eye moved sideways by (dxdz zp, dydz zp) through
    // an image window moved by (-dxdz, -dydz), so the plane at zp stays where it was on screen.
    double kx = 0, ky = 0, ex = 0, ey = 0;
    auto shear = [&](double dxdz, double dydz, double zp) {
      kx += dxdz, ky += dydz, ex += dxdz * zp, ey += dydz * zp;
    };
    if (cam->GetStereo() && cam->GetEyeAngle() != 0.0)
    {
      const double t = std::tan(vtkMath::RadiansFromDegrees(cam->GetEyeAngle()) * 0.5);
      shear(cam->GetLeftEye() ? -t : t, 0.0, cam->GetDistance());
    }
    const double* vs = cam->GetViewShear();
    if (vs[0] != 0.0 || vs[1] != 0.0)
    {
      shear(vs[0], vs[1], vs[2] * cam->GetDistance());
    }
    c.Eye = c.Eye + c.Right * ex + c.Up * ey;
    c.Cx -= kx / c.HalfW;
    c.Cy -= ky / c.HalfH;
  }
  return c;
}

void Camera::DefaultView(vtkCamera* cam, const Box3& bounds)
{
  const Vec3 e = bounds.hi - bounds.lo;
  const double widest = std::max({ e.x, e.y, e.z });
  cam->SetFocalPoint(0, 0, 0);
  if (e.z < 0.05 * widest && e.z <= e.x)
  {
    cam->SetPosition(0, 0, 1);
    cam->SetViewUp(0, 1, 0);
  }
  else
  {
    const bool thinX = e.x < 0.05 * widest && e.x < e.y;
    cam->SetPosition(thinX ? -1 : 0, thinX ? 0 : -1, 0);
    cam->SetViewUp(0, 0, 1);
  }
}

void Camera::Frame(vtkCamera* cam, const Box3& b, double azimuth, double elevation, double zoom, double aspect)
{
  // A non-finite angle turns every ray into NaN: an image of nothing, or a crash in a caster.
  if (!std::isfinite(azimuth) || !std::isfinite(elevation) || !(zoom > 0) || !std::isfinite(zoom))
  {
    throw Error("camera azimuth and elevation must be finite and zoom positive and finite");
  }
  const Vec3 centre = b.Center();
  const double radius = std::max(0.5 * b.Diagonal(), 1e-12);
  const Vec3 dir = Normalize(Vec3(cam->GetDirectionOfProjection()));
  // The narrower of the two half angles must hold the bounding sphere.
  const double half = vtkMath::RadiansFromDegrees(cam->GetViewAngle()) * 0.5;
  const double a = aspect > 0 && std::isfinite(aspect) ? aspect : 1.0;
  const double narrow = cam->GetUseHorizontalViewAngle() ? (a > 1 ? std::atan(std::tan(half) / a) : half)
                                                         : (a < 1 ? std::atan(std::tan(half) * a) : half);
  const double dist = radius / std::sin(narrow);
  const Vec3 eye = centre - dir * dist;
  cam->SetFocalPoint(centre.x, centre.y, centre.z);
  cam->SetPosition(eye.x, eye.y, eye.z);
  cam->SetParallelScale(a < 1 ? radius / a : radius); // the scale is half the height
  cam->Azimuth(azimuth);
  cam->Elevation(elevation);
  cam->OrthogonalizeViewUp();
  cam->Zoom(zoom);
  cam->SetClippingRange(std::max(dist - 2 * radius, 1e-3 * dist), dist + 2 * radius);
}

namespace
{
// Half extents (right, up) and depth (along the view) of `b` about its centre, seen along the
// orthonormal frame (r, u, f): exactly its corners, or a cylinder about `axis` holding them.
void ViewExtents(const Box3& b, const Vec3& r, const Vec3& u, const Vec3& f, const Vec3& axis, Camera::Fit fit,
  double& x, double& y, double& z)
{
  const Vec3 h = b.Size() * 0.5;
  x = y = z = 0;
  if (fit == Camera::Fit::View)
  {
    for (int k = 0; k < 8; ++k)
    {
      const Vec3 d{ (k & 1) ? h.x : -h.x, (k & 2) ? h.y : -h.y, (k & 4) ? h.z : -h.z };
      x = std::max(x, std::fabs(Dot(d, r)));
      y = std::max(y, std::fabs(Dot(d, u)));
      z = std::max(z, std::fabs(Dot(d, f)));
    }
    return;
  }
  // The cylinder: its half height along `axis`, its radius across it.
  double height = 0, radius = 0;
  for (int k = 0; k < 8; ++k)
  {
    const Vec3 d{ (k & 1) ? h.x : -h.x, (k & 2) ? h.y : -h.y, (k & 4) ? h.z : -h.z };
    const double along = Dot(d, axis);
    height = std::max(height, std::fabs(along));
    radius = std::max(radius, Length(d - axis * along));
  }
  const double tilt = std::fabs(Dot(f, axis)); // the sine of the elevation
  const double level = std::sqrt(std::max(0.0, 1.0 - tilt * tilt));
  x = radius;
  y = height * level + radius * tilt;
  z = radius * level + height * tilt;
}

// How far along -f from `c` the eye leaves box `b`.
double ExitDistance(const Box3& b, const Vec3& c, const Vec3& f)
{
  const double o[3] = { c.x, c.y, c.z }, d[3] = { -f.x, -f.y, -f.z };
  const double lo[3] = { b.lo.x, b.lo.y, b.lo.z }, hi[3] = { b.hi.x, b.hi.y, b.hi.z };
  double exit = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
  {
    if (std::fabs(d[a]) > 1e-12)
    {
      exit = std::min(exit, ((d[a] > 0 ? hi[a] : lo[a]) - o[a]) / d[a]);
    }
  }
  return std::isfinite(exit) ? std::max(exit, 0.0) : 0.0;
}
} // namespace

void Camera::FrameObject(vtkCamera* cam, const Box3& object, const Box3& data, double azimuth, double elevation,
  double zoom, double aspect, Fit fit)
{
  if (!std::isfinite(azimuth) || !std::isfinite(elevation) || !(zoom > 0) || !std::isfinite(zoom))
  {
    throw Error("camera azimuth and elevation must be finite and zoom positive and finite");
  }
  Box3 box = object.Empty() ? data : object;
  const Vec3 centre = box.Center();
  const double size = std::max(data.Diagonal(), 1e-12);
  // A single visible voxel still gets a frame: a thousandth of the data's size at least.
  box.Expand(centre + Vec3{ 5e-4, 5e-4, 5e-4 } * size);
  box.Expand(centre - Vec3{ 5e-4, 5e-4, 5e-4 } * size);
  const Vec3 axis = Normalize(Vec3(cam->GetViewUp()));
  const Vec3 dir0 = Normalize(Vec3(cam->GetDirectionOfProjection()));
  cam->SetFocalPoint(centre.x, centre.y, centre.z);
  cam->SetPosition(centre.x - dir0.x, centre.y - dir0.y, centre.z - dir0.z);
  cam->Azimuth(azimuth);
  cam->Elevation(elevation);
  cam->OrthogonalizeViewUp();
  const Vec3 f = Normalize(Vec3(cam->GetDirectionOfProjection()));
  const Vec3 u = Normalize(Vec3(cam->GetViewUp()));
  const Vec3 r = Cross(f, u);
  double x, y, z;
  ViewExtents(box, r, u, f, axis, fit, x, y, z);

  const double a = aspect > 0 && std::isfinite(aspect) ? aspect : 1.0;
  const double half = vtkMath::RadiansFromDegrees(cam->GetViewAngle()) * 0.5;
  const double tanV = cam->GetUseHorizontalViewAngle() ? std::tan(half) / a : std::tan(half);
  const double tanH = tanV * a;
  // Perspective: each corner within the frame at its own depth; the orbit's cylinder as if its
  // widest circle stood at its nearest point.
  double dist = std::max(x / (FitFraction * tanH), y / (FitFraction * tanV)) + z;
  if (fit == Fit::View)
  {
    const Vec3 h = box.Size() * 0.5;
    dist = 0;
    for (int k = 0; k < 8; ++k)
    {
      const Vec3 d{ (k & 1) ? h.x : -h.x, (k & 2) ? h.y : -h.y, (k & 4) ? h.z : -h.z };
      dist = std::max({ dist, std::fabs(Dot(d, r)) / (FitFraction * tanH) - Dot(d, f),
        std::fabs(Dot(d, u)) / (FitFraction * tanV) - Dot(d, f) });
    }
  }
  const double outside = 1.02 * ExitDistance(data, centre, f) + 1e-6 * size;
  if (!cam->GetParallelProjection() && dist < outside)
  {
    // Closer would put the eye among the cells: stay out and narrow the angle to the same fit.
    const double narrowed = std::atan(std::tan(half) * (dist - z) / (outside - z));
    cam->SetViewAngle(vtkMath::DegreesFromRadians(2.0 * narrowed));
    dist = outside;
  }
  dist = std::max(dist, outside);
  const Vec3 eye = centre - f * dist;
  cam->SetPosition(eye.x, eye.y, eye.z);
  cam->SetParallelScale(std::max(y, x / a) / FitFraction); // half the height
  cam->Zoom(zoom);
  const double reach = 0.5 * size;
  cam->SetClippingRange(std::max(dist - reach - Length(data.Center() - centre), 1e-3 * dist),
    dist + reach + Length(data.Center() - centre));
}

Ray Camera::Generate(double px, double py) const
{
  // NDC in [-1, 1], y up; pixel centres sit at +0.5.
  const double sx = (2.0 * (px + 0.5) / W - 1.0 + Cx) * HalfW;
  const double sy = (1.0 - 2.0 * (py + 0.5) / H + Cy) * HalfH;
  Ray r;
  if (Parallel)
  {
    r.org = Eye + Right * sx + Up * sy;
    r.dir = Fwd;
  }
  else
  {
    r.org = Eye;
    r.dir = Normalize(Fwd + Right * sx + Up * sy);
  }
  return r;
}
} // namespace art
