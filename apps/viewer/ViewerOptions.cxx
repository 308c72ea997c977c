#include "ViewerOptions.h"

#include "DataLoader.h"

#include "TransferFunction.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace view
{
namespace
{
long long ParseCount(const std::string& s, const std::string& what)
{
  char* end = nullptr;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || v < 1)
  {
    throw UsageError(what + " expects a positive whole number, got '" + s + "'");
  }
  return v;
}
} // namespace

std::string UsageText()
{
  const art::InputFormatList f = art::InputFormats();
  return "usage: adaptivert-view [options] FILE\n\n"
         "Shows a volume, a mesh or a triangle scene in a window:\n"
         "  volumes    " + f.volumes + "\n"
         "  meshes     " + f.meshes + "\n"
         "  surfaces   " + f.surfaces + "\n"
         "  and        " + f.any + "\n"
         "Volumes are reduced to adaptive tets in the background (nested levels from one run,\n"
         "fitted where the transfer function shows the data, vertices relocated; `adaptivert\n"
         "render` reduces anisotropically by default, --refinement anisotropic here, without\n"
         "relocation) and ray cast cell by cell (vtkTetRayCastMapper);\n"
         "triangle scenes are ray traced through the TriangleGrid surface tracer.\n\n"
         "options:\n"
         "  --size WxH           window size in pixels (default 800x600)\n"
         "  --tets N[,N...]      reduction levels for a volume, counts or P% of the voxel count\n"
         "                       (default 2000,10000,40000)\n"
         "  --refinement R       how the levels are made, as `adaptivert render --refinement`: bisection\n"
         "                       (default; nested, vertices relocated), edge, or anisotropic (MMG3D to\n"
         "                       the voxels' Hessian metric; each level adapted anew, not nested)\n"
         "  --array NAME         point (or cell) array to show (default: the active scalars);\n"
         "                       NAME:magnitude or NAME:N for a vector's magnitude or component N\n"
         "  --tf NAME|FILE       transfer function: auto (ct-skin-bone on CT in Hounsfield units, else\n"
         "                       from the data: background clear, a grey ramp over its robust range,\n"
         "                       labels in distinct colours), ct-skin-bone, ct-bone, grey-ramp,\n"
         "                       constant, labels, or a file of\n"
         "                       'scalar r g b opacity' lines or a ParaView preset .json (default auto)\n"
         "  --label-colours MODE a label mesh (cell array 'label'): values (default: each label's colour,\n"
         "                       brightness and opacity from the values it carries, if any), flat (each\n"
         "                       label in its colour), off (the labels ignored)\n"
         "  --frame patient|vtk  place a volume in LPS patient coordinates (default) or as VTK's readers\n"
         "                       and ParaView do (origin and spacing)\n"
         "  --raw-dims X,Y,Z --raw-type T [--raw-spacing X,Y,Z --raw-header B --raw-endian little|big]\n"
         "                       read FILE as raw voxels\n"
         "  --script FILE        run scripted actions (one per line: key K | wait S | wait-reduction |\n"
         "                       azimuth DEG | elevation DEG | roll DEG | zoom F | drag DX DY |\n"
         "                       screenshot FILE)\n"
         "  --screenshot OUT.png after the script (or, without one, the reduction) save the window, exit\n"
         "  -h, --help           this text\n\n"
         "keys: [ ] coarser/finer level, 1-9 pick a level, i iso-surface, + - iso-value,\n"
         "      t early-termination threshold, x exact/trapezoid rule, m mesh edges,\n"
         "      c clipping plane (drag it), h help, s screenshot, r reset camera, q quit;\n"
         "      mouse: trackball camera.\n\n"
         "examples:\n"
         "  adaptivert-view data/ct-head-128.mha\n"
         "  adaptivert-view --tets 1000,5000,20000 --size 400x400 data/ct-head-128.mha\n"
         "  xvfb-run -a adaptivert-view --script demo.txt --screenshot out.png data/ct-head-128.mha\n";
}

ViewerOptions ParseOptions(const std::vector<std::string>& args)
{
  ViewerOptions o;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    std::string a = args[i], value;
    const bool isOption = a.size() > 1 && a[0] == '-';
    if (!isOption)
    {
      if (!o.File.empty())
      {
        throw UsageError("expects one FILE, got '" + o.File + "' and '" + a + "'");
      }
      o.File = a;
      continue;
    }
    if (a == "-h" || a == "--help")
    {
      o.Help = true;
      continue;
    }
    const auto eq = a.find('=');
    bool inlineValue = false;
    if (eq != std::string::npos)
    {
      value = a.substr(eq + 1);
      a = a.substr(0, eq);
      inlineValue = true;
    }
    static const char* withValue[] = { "--size", "--tets", "--refinement", "--array", "--tf", "--label-colours", "--script",
      "--screenshot", "--frame", "--raw-dims", "--raw-type", "--raw-spacing", "--raw-header", "--raw-endian",
      "--raw-components" };
    if (std::find(std::begin(withValue), std::end(withValue), a) == std::end(withValue))
    {
      throw UsageError("unknown option '" + a + "'");
    }
    if (!inlineValue)
    {
      if (i + 1 >= args.size())
      {
        throw UsageError("option '" + a + "' needs a value");
      }
      value = args[++i];
    }
    if (a == "--frame")
    {
      if (value != "patient" && value != "vtk")
      {
        throw UsageError("--frame is patient or vtk, got '" + value + "'");
      }
      o.Load.Placement = art::ParseFrame(value);
    }
    else if (a.rfind("--raw-", 0) == 0)
    {
      try
      {
        art::SetRawOption(o.Load.Raw, a.substr(2), value);
      }
      catch (const std::invalid_argument& e)
      {
        throw UsageError(e.what());
      }
    }
    else if (a == "--size")
    {
      const auto x = value.find_first_of("xX");
      if (x == std::string::npos)
      {
        throw UsageError("--size expects WxH, got '" + value + "'");
      }
      const long long w = ParseCount(value.substr(0, x), "--size"), h = ParseCount(value.substr(x + 1), "--size");
      if (w < 64 || h < 64 || w > 8192 || h > 8192)
      {
        throw UsageError("--size must be within 64..8192 on each side, got '" + value + "'");
      }
      o.Width = static_cast<int>(w);
      o.Height = static_cast<int>(h);
    }
    else if (a == "--tets")
    {
      o.TetsGiven = true;
      o.Tets.clear();
      o.TetPercents.clear();
      std::stringstream ss(value);
      std::string item;
      while (std::getline(ss, item, ','))
      {
        if (!item.empty() && item.back() == '%')
        {
          char* end = nullptr;
          const double p = std::strtod(item.c_str(), &end);
          if (end != item.c_str() + item.size() - 1 || !(p > 0 && p <= 500))
          {
            throw UsageError("--tets percentages must be in (0, 500], got " + item);
          }
          o.TetPercents.push_back(p);
          continue;
        }
        const long long n = ParseCount(item, "--tets");
        if (n < 6)
        {
          throw UsageError("--tets budgets must be at least 6, got " + item);
        }
        o.Tets.push_back(n);
      }
      if (o.Tets.empty() && o.TetPercents.empty())
      {
        throw UsageError("--tets expects N[,N...] (or P% of the voxel count)");
      }
      std::sort(o.Tets.begin(), o.Tets.end());
      o.Tets.erase(std::unique(o.Tets.begin(), o.Tets.end()), o.Tets.end());
    }
    else if (a == "--refinement")
    {
      if (value != "bisection" && value != "edge" && value != "anisotropic")
      {
        throw UsageError("--refinement is bisection, edge or anisotropic, got '" + value + "'");
      }
      o.Refinement = value;
    }
    else if (a == "--label-colours")
    {
      if (value != "values" && value != "flat" && value != "off")
      {
        throw UsageError("--label-colours is values, flat or off, got '" + value + "'");
      }
      o.LabelColours = value;
    }
    else if (a == "--array")
    {
      if (value.empty())
      {
        throw UsageError("--array expects an array name");
      }
      o.Array = value;
    }
    else if (a == "--tf")
    {
      // A name is a preset; anything that looks like a path is a node file (read at load time).
      const auto names = art::TransferFunction::PresetNames();
      if (value.find_first_of("./") == std::string::npos &&
        std::find(names.begin(), names.end(), value) == names.end())
      {
        std::string all;
        for (const auto& n : names)
        {
          all += (all.empty() ? "" : ", ") + n;
        }
        throw UsageError("--tf: unknown preset '" + value + "' (known: " + all + ", or a file)");
      }
      o.TransferFunction = value;
      o.TfGiven = true;
    }
    else if (a == "--script")
    {
      o.Script = value;
    }
    else
    {
      if (value.size() < 5 || value.substr(value.size() - 4) != ".png")
      {
        throw UsageError("--screenshot expects a .png file, got '" + value + "'");
      }
      o.Screenshot = value;
    }
  }
  if (!o.Help && o.File.empty())
  {
    throw UsageError("needs a FILE to show");
  }
  if (o.Tets.empty() && o.TetPercents.empty())
  {
    o.Tets = { 2000, 10000, 40000 };
  }
  if ((o.Load.Raw.Given() || !o.Load.Raw.Type.empty()) && !(o.Load.Raw.Given() && !o.Load.Raw.Type.empty()))
  {
    throw UsageError("a raw volume needs both --raw-dims X,Y,Z and --raw-type TYPE");
  }
  return o;
}

std::vector<long long> Budgets(const ViewerOptions& o, long long voxels)
{
  std::vector<long long> b = o.Tets;
  for (double p : o.TetPercents)
  {
    const long long n = std::llround(p / 100.0 * static_cast<double>(voxels));
    if (n < 6)
    {
      throw UsageError("--tets " + std::to_string(p) + "% is " + std::to_string(n) + " tets for this volume; at least 6");
    }
    b.push_back(n);
  }
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  return b;
}
} // namespace view
