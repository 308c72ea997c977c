// adaptivert render INPUT -o OUT: renders a volume, tet mesh or triangle scene without a window.
#include "cli/Command.h"
#include "AtomicFile.h"
#include "Camera.h"
#include "Error.h"
#include "ImageIO.h"
#include "rendering/Render.h"
#include "cli/LoadOptions.h"

#include <vtkCamera.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

namespace cli
{
std::vector<Renderer>& Renderers()
{
  static std::vector<Renderer> r;
  return r;
}

View ViewFromOptions(const Options& o)
{
  View v;
  o.GetSize("size", v.width, v.height);
  v.output = o.Get("output");
  if (v.output.empty())
  {
    throw UsageError("needs -o OUT.png (or .exr, .tif)");
  }
  if (!art::IsImageExtension(v.output))
  {
    throw UsageError("output must be .png, .exr or .tif: '" + v.output + "'");
  }
  std::istringstream bg(o.Get("background"));
  char comma;
  if (!(bg >> v.background[0] >> comma >> v.background[1] >> comma >> v.background[2]))
  {
    throw UsageError("--background expects R,G,B in [0, 1], got '" + o.Get("background") + "'");
  }
  return v;
}

double Zoom(const Options& o)
{
  const double zoom = o.GetDouble("zoom");
  if (!(zoom > 0 && std::isfinite(zoom)))
  {
    throw UsageError("--zoom expects a positive factor, got '" + o.Get("zoom") + "'");
  }
  return zoom;
}

art::Vec3 ParseDirection(const std::string& text, const char* option)
{
  std::istringstream in(text);
  art::Vec3 v;
  char c1 = 0, c2 = 0;
  if (!(in >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || !(in >> std::ws).eof() ||
    !art::IsFinite(v) || !(art::Length(v) > 0))
  {
    throw UsageError(std::string(option) + " expects a non-zero direction X,Y,Z, got '" + text + "'");
  }
  return art::Normalize(v);
}

void ApplyViewUp(const Options& o, vtkCamera* cam)
{
  if (!o.Has("view-up"))
  {
    return;
  }
  const art::Vec3 up = ParseDirection(o.Get("view-up"), "--view-up");
  const art::Vec3 dir = art::Normalize(art::Vec3(cam->GetDirectionOfProjection()));
  if (std::abs(art::Dot(up, dir)) > 0.999)
  {
    throw UsageError("--view-up " + o.Get("view-up") + " is along the view direction; give one across it");
  }
  cam->SetViewUp(up.x, up.y, up.z);
  cam->OrthogonalizeViewUp();
}

double Roll(const Options& o)
{
  const double roll = o.GetDouble("roll");
  if (!std::isfinite(roll))
  {
    throw UsageError("--roll expects degrees, got '" + o.Get("roll") + "'");
  }
  return roll;
}

Json CameraJson(vtkCamera* cam)
{
  const double* p = cam->GetPosition();
  const double* f = cam->GetFocalPoint();
  const double* u = cam->GetViewUp();
  Json j;
  j.Set("position", std::vector<double>(p, p + 3)).Set("focal_point", std::vector<double>(f, f + 3))
    .Set("view_up", std::vector<double>(u, u + 3)).Set("view_angle", cam->GetViewAngle())
    .Set("parallel", cam->GetParallelProjection() != 0).Set("parallel_scale", cam->GetParallelScale());
  return j;
}

void SetupCamera(const Options& o, const art::Box3& object, const art::Box3& bounds, vtkCamera* cam,
  double defaultElevation)
{
  const std::string fit = o.Get("fit").empty() ? "view" : o.Get("fit");
  if (fit != "view" && fit != "orbit")
  {
    throw UsageError("--fit expects view or orbit, got '" + fit + "'");
  }
  art::Camera::DefaultView(cam, bounds);
  ApplyViewUp(o, cam);
  cam->SetParallelProjection(o.Flag("parallel"));
  const View view = ViewFromOptions(o);
  const double elevation = o.Has("elevation") ? o.GetDouble("elevation") : defaultElevation;
  art::Camera::FrameObject(cam, object, bounds, o.GetDouble("azimuth"), elevation, Zoom(o),
    double(view.width) / double(view.height), fit == "orbit" ? art::Camera::Fit::Orbit : art::Camera::Fit::View);
  cam->Roll(Roll(o));
}

// The tet renderer's options that reduce a volume before casting (or cast its voxels): a tet mesh
// renders as it is, and --tets 500 on a mesh drew all its 2347 tets without a word.
static bool VolumeOnly(const std::string& option)
{
  static const std::set<std::string> only = { "tets", "max-error", "refinement", "relocate", "no-relocate", "plain-reduction",
    "mesh-cache", "reference", "save-mesh" };
  return only.count(option) > 0 || (IsLoadOption(option) && option != "frame"); // --frame: also --error's volume
}

bool IsRenderOption(const std::string& option)
{
  const Command* render = FindCommand("render");
  Options declared;
  if (render && render->declare)
  {
    render->declare(declared);
  }
  AddCommonOptions(declared);
  const auto& names = declared.Declared();
  return std::find(names.begin(), names.end(), option) != names.end();
}

bool OptionAppliesTo(const std::string& option, art::DataKind kind)
{
  if (kind == art::DataKind::Mesh && VolumeOnly(option))
  {
    return false;
  }
  bool declaredElsewhere = false;
  for (const auto& r : Renderers())
  {
    Options declared;
    if (r.declare)
    {
      r.declare(declared);
    }
    const auto& names = declared.Declared();
    if (std::find(names.begin(), names.end(), option) == names.end())
    {
      continue;
    }
    if (std::find(r.kinds.begin(), r.kinds.end(), kind) != r.kinds.end())
    {
      return true;
    }
    declaredElsewhere = true;
  }
  return !declaredElsewhere;
}
} // namespace cli

namespace
{
void Declare(cli::Options& o)
{
  o.Add("output", 'o', "FILE", "image to write: .png (8-bit), .exr or .tif (float)");
  o.Add("size", 's', "WxH", "image size in pixels", "800x600");
  o.Add("azimuth", 0, "DEG", "rotate the camera about the view-up axis", "0");
  o.Add("elevation", 0, "DEG", "rotate the camera up over the focal point", "0");
  o.Add("zoom", 0, "F", "zoom factor (>1 is closer)", "1");
  o.Add("view-up", 0, "X,Y,Z", "the direction that is up in the image before --azimuth and --elevation (default: +z, "
    "or +y for data flat in z)");
  o.Add("roll", 0, "DEG", "turn the image about the view direction, after --azimuth and --elevation", "0");
  o.Add("parallel", 0, "", "parallel instead of perspective projection");
  o.Add("fit", 0, "view|orbit", "frame the visible object to 85% of the image as this view sees it, or (orbit) "
    "at one distance for every azimuth, as batch orbits need", "view");
  o.Add("background", 0, "R,G,B", "background colour", "0,0,0");
  for (const auto& r : cli::Renderers())
  {
    if (r.declare)
    {
      r.declare(o);
    }
  }
}

// An option of another renderer (--tets on a triangle scene, --opacity on a volume) would be
// ignored without a word: it is a usage error instead.
void RefuseOthersOptions(const cli::Options& o, art::DataKind kind)
{
  for (const auto& r : cli::Renderers())
  {
    cli::Options declared;
    if (r.declare)
    {
      r.declare(declared);
    }
    for (const std::string& name : declared.Declared())
    {
      if (o.Has(name) && !cli::OptionAppliesTo(name, kind))
      {
        throw cli::UsageError("--" + name + " does not apply to a " + art::KindName(kind) +
          (cli::VolumeOnly(name) ? " (it reduces or casts a voxel volume; a tet mesh renders as it is)" : ""));
      }
    }
  }
}

int Run(const cli::Options& o)
{
  if (o.Positional().size() != 1)
  {
    throw cli::UsageError("needs exactly one INPUT");
  }
  const std::string input = o.Positional()[0];
  cli::Zoom(o); // usage errors before any loading
  cli::Roll(o);
  if (o.Has("view-up"))
  {
    cli::ParseDirection(o.Get("view-up"), "--view-up");
  }
  cli::ViewFromOptions(o);
  const art::DataKind kind = art::KindOf(input, cli::LoadOptionsFrom(o));
  {
    // An output that cannot be written (a folder that does not exist or is read-only, a folder's
    // name) is said before loading and reducing: it was said at the end, after a minute of
    // reducing a large volume. The trial file is removed as it goes.
    art::AtomicFile trial(o.Get("output"));
  }
  for (const auto& r : cli::Renderers())
  {
    for (art::DataKind k : r.kinds)
    {
      if (k == kind)
      {
        RefuseOthersOptions(o, kind);
        return r.run(o, input);
      }
    }
  }
  throw art::Error(std::string("rendering a ") + art::KindName(kind) + " is not available in this build", input);
}

cli::Registrar reg({ "render", "render a volume, tet mesh or triangle scene to an image, without a window",
  "adaptivert render [options] INPUT -o OUT.png",
  "  adaptivert render data/ct-head-128.mha -o head.png --size 500x500\n"
  "  adaptivert render data/am_underworks.ply -o room.exr --azimuth 30\n",
  Declare, Run });
} // namespace
