// TransferFunction from files: ParaView's exported JSON presets and plain text
// ("scalar r g b opacity" lines, an optional unit distance).
#include "TransferFunction.h"

#include "Error.h"
#include "RegularFile.h"

#include <vtkColorTransferFunction.h>
#include <vtkNew.h>
#include <vtkPiecewiseFunction.h>
#include <vtkVolumeProperty.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace art
{
namespace
{
// A preset as ParaView's "Export" writes it: a list of one object (or the object) with
// "RGBPoints" [x r g b ...], optional "ColorSpace" and optional "Points" [x opacity midpoint
// sharpness ...]; without "Points", opacity ramps from 0 to 1 over the colour points' range, as
// ParaView starts a volume's opacity. Read through VTK's own functions, so its colour spaces,
// midpoints and sharpness are followed (FromVTK).
TransferFunction FromParaViewPreset(std::istream& in, const std::string& path)
{
  nlohmann::json j;
  try
  {
    j = nlohmann::json::parse(in);
  }
  catch (const nlohmann::json::exception& e)
  {
    throw Error(std::string("not a ParaView preset (JSON): ") + e.what(), path);
  }
  if (j.is_array())
  {
    if (j.size() != 1)
    {
      throw Error("holds " + std::to_string(j.size()) + " presets; export the one to use alone", path);
    }
    j = j[0];
  }
  if (!j.is_object())
  {
    throw Error("not a ParaView preset: expected an object with \"RGBPoints\"", path);
  }
  const std::string name = j.contains("Name") && j["Name"].is_string() ? j["Name"].get<std::string>() : "";
  auto numbers = [&](const char* key) {
    std::vector<double> v;
    const auto& a = j[key];
    if (!a.is_array() || a.size() % 4 != 0 || a.empty())
    {
      throw Error(std::string("\"") + key + "\" must be a non-empty list of 4 numbers per point", path);
    }
    for (const auto& x : a)
    {
      if (!x.is_number() || !std::isfinite(x.get<double>()))
      {
        throw Error(std::string("\"") + key + "\" holds something other than finite numbers", path);
      }
      v.push_back(x.get<double>());
    }
    return v;
  };
  if (!j.contains("RGBPoints"))
  {
    throw Error("preset '" + name + "' has no \"RGBPoints\" (categorical presets are not supported)", path);
  }
  const std::vector<double> rgb = numbers("RGBPoints");
  vtkNew<vtkColorTransferFunction> ctf;
  const std::string space = j.contains("ColorSpace") && j["ColorSpace"].is_string() ? j["ColorSpace"].get<std::string>() : "RGB";
  if (space == "RGB")
    ctf->SetColorSpaceToRGB();
  else if (space == "HSV")
    ctf->SetColorSpaceToHSV();
  else if (space == "Lab")
    ctf->SetColorSpaceToLab();
  else if (space == "Lab/CIEDE2000")
    ctf->SetColorSpaceToLabCIEDE2000();
  else if (space == "Diverging")
    ctf->SetColorSpaceToDiverging();
  else if (space == "Step")
    ctf->SetColorSpaceToStep();
  else
    throw Error("unknown \"ColorSpace\" '" + space + "'", path);
  for (std::size_t i = 0; i < rgb.size(); i += 4)
  {
    ctf->AddRGBPoint(rgb[i], rgb[i + 1], rgb[i + 2], rgb[i + 3]);
  }
  vtkNew<vtkPiecewiseFunction> otf;
  if (j.contains("Points"))
  {
    const std::vector<double> o = numbers("Points");
    for (std::size_t i = 0; i < o.size(); i += 4)
    {
      otf->AddPoint(o[i], o[i + 1], o[i + 2], o[i + 3]);
    }
  }
  else
  {
    double r[2];
    ctf->GetRange(r);
    otf->AddPoint(r[0], 0.0);
    otf->AddPoint(r[1], 1.0);
  }
  vtkNew<vtkVolumeProperty> p;
  p->SetColor(ctf);
  p->SetScalarOpacity(otf);
  return TransferFunction::FromVTK(p);
}
} // namespace

bool TransferFunction::NamesFile(const std::string& tf)
{
  return std::filesystem::exists(tf) || tf.find_first_of("./") != std::string::npos;
}

TransferFunction TransferFunction::FromFile(const std::string& path)
{
  try
  {
    return ReadFile(path);
  }
  catch (const Error& e)
  {
    if (e.file().empty()) // the nodes' own checks (the constructor's) do not know the file
    {
      throw Error(e.problem(), path);
    }
    throw;
  }
}

TransferFunction TransferFunction::ReadFile(const std::string& path)
{
  RequireRegularFile(path); // a FIFO or /dev/zero would block or read forever
  std::ifstream in(path);
  if (!in)
  {
    throw Error("cannot open transfer-function file", path);
  }
  // A byte-order mark (Notepad's UTF-8) is skipped.
  char bom[3] = { 0, 0, 0 };
  in.read(bom, 3);
  if (!(in.gcount() == 3 && bom[0] == '\xEF' && bom[1] == '\xBB' && bom[2] == '\xBF'))
  {
    in.clear();
    in.seekg(0);
  }
  // A ParaView preset starts with '[' or '{'; our own format with a number or a comment.
  in >> std::ws;
  if (in.peek() == '[' || in.peek() == '{')
  {
    return FromParaViewPreset(in, path);
  }
  std::vector<Node> nodes;
  double unit = 1.0;
  std::string line;
  for (int no = 1; std::getline(in, line); ++no)
  {
    const auto hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    // Values may be separated by commas too (a spreadsheet's CSV); a line without any digit before
    // the first node is its header.
    std::replace(line.begin(), line.end(), ',', ' ');
    if (nodes.empty() && line.find_first_of("0123456789") == std::string::npos &&
      line.find_first_not_of(" \t\r") != std::string::npos && line.find("unit-distance") == std::string::npos)
    {
      continue;
    }
    std::istringstream ss(line);
    std::string first;
    if (!(ss >> first))
    {
      continue;
    }
    if (first == "unit-distance")
    {
      if (!(ss >> unit) || !(unit > 0))
      {
        throw Error("line " + std::to_string(no) + ": unit-distance needs a positive number", path);
      }
      continue;
    }
    Node n{};
    std::istringstream all(line);
    std::string extra;
    if (!(all >> n.s >> n.rgb[0] >> n.rgb[1] >> n.rgb[2] >> n.alpha) || (all >> extra))
    {
      throw Error("line " + std::to_string(no) + ": expected 'scalar r g b opacity' (five numbers, separated by "
        "spaces or commas), got '" + line.substr(0, 60) + "'", path);
    }
    for (double c : { n.rgb[0], n.rgb[1], n.rgb[2], n.alpha })
    {
      if (!(c >= 0.0 && c <= 1.0))
      {
        throw Error("line " + std::to_string(no) + ": colour and opacity must lie in [0, 1]", path);
      }
    }
    nodes.push_back(n);
  }
  if (nodes.empty())
  {
    throw Error("no control points (expected lines 'scalar r g b opacity')", path);
  }
  return TransferFunction(std::move(nodes), unit);
}
} // namespace art
