// Render: the `adaptivert render` subcommand dispatches on the input's kind to a renderer that
// registers itself here (the tet caster for volumes and meshes, the surface tracer for
// triangle scenes). The options every renderer shares are declared once in commands/RenderCommand.cxx.
#ifndef adaptivert_Render_h
#define adaptivert_Render_h

#include "Box3.h"
#include "Vec3.h"
#include "DataLoader.h"
#include "cli/Json.h"
#include "cli/Options.h"

#include <string>
#include <vector>

class vtkCamera;

namespace cli
{
struct Renderer
{
  std::string name;                 ///< "tets", "surface"
  std::vector<art::DataKind> kinds; ///< inputs it renders
  void (*declare)(Options&) = nullptr;                       ///< its own options
  int (*run)(const Options&, const std::string& input) = nullptr; ///< exit code
};

std::vector<Renderer>& Renderers();

/// False when only other kinds' renderers declare --option (--tets for a surface, --opacity for a
/// volume); `render` refuses such options, and batch jobs leave them out of those frames.
bool OptionAppliesTo(const std::string& option, art::DataKind kind);
/// Whether `render` declares --option (its own, a renderer's or the common ones), by long name.
bool IsRenderOption(const std::string& option);

struct RendererRegistrar
{
  explicit RendererRegistrar(Renderer r) { Renderers().push_back(std::move(r)); }
};

/// The shared view options: --size WxH, --azimuth, --elevation, --zoom, --parallel.
struct View
{
  int width = 800, height = 600;
  std::string output; ///< -o
  float background[3] = { 0.f, 0.f, 0.f };
};
View ViewFromOptions(const Options& o);
/// Frames `object` (the visible part of data within `bounds`) with the shared camera options
/// (art::Camera::FrameObject; --fit). The default view looks along +y with +z up (the anterior
/// view of a scan in patient coordinates), which also suits most scenes; --view-up replaces the
/// up direction, --roll turns the image last; `defaultElevation` stands in for --elevation when it
/// is not given.
void SetupCamera(const Options& o, const art::Box3& object, const art::Box3& bounds, vtkCamera* cam,
  double defaultElevation = 0.0);
/// The camera as render's --json reports it: position, focal_point, view_up, view_angle,
/// parallel, parallel_scale (what a vtkCamera needs to draw the same view).
Json CameraJson(vtkCamera* cam);
/// --view-up applied to `cam` (kept square to its view direction); nothing without it.
void ApplyViewUp(const Options& o, vtkCamera* cam);
/// --roll in degrees.
double Roll(const Options& o);
/// A unit direction from "X,Y,Z"; a usage error naming `option` unless finite and non-zero.
art::Vec3 ParseDirection(const std::string& text, const char* option);
/// --zoom, positive and finite.
double Zoom(const Options& o);
} // namespace cli

#endif
