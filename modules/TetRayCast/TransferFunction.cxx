#include "TransferFunction.h"
#include "DataTransferFunction.h"

#include "TetMesh.h"

#include "Error.h"
#include "RegularFile.h"
#include "MeanSpacing.h"

#include <vtkColorTransferFunction.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkVolumeProperty.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <filesystem>
#include <sstream>

namespace art
{
namespace
{
double TauOf(double alpha, double unit)
{
  const double a = std::min(std::max(alpha, 0.0), 1.0 - 1e-6);
  return -std::log1p(-a) / unit;
}
} // namespace

TransferFunction::TransferFunction(std::vector<Node> nodes, double unitDistance)
  : Unit(unitDistance)
{
  if (nodes.empty())
  {
    throw Error("transfer function has no control points");
  }
  if (!(unitDistance > 0.0) || !std::isfinite(unitDistance))
  {
    throw Error("transfer function unit distance must be positive");
  }
  std::stable_sort(nodes.begin(), nodes.end(), [](const Node& a, const Node& b) { return a.s < b.s; });
  for (Node& n : nodes)
  {
    if (!std::isfinite(n.s) || !std::isfinite(n.alpha))
    {
      throw Error("transfer function has a non-finite control point");
    }
    for (double& c : n.rgb)
    {
      c = std::min(std::max(c, 0.0), 1.0);
    }
    n.alpha = std::min(std::max(n.alpha, 0.0), 1.0);
    n.tau = TauOf(n.alpha, Unit);
    if (!N.empty() && N.back().s == n.s)
    {
      N.back() = n;
    }
    else
    {
      N.push_back(n);
    }
  }
  // Locate's table spreads the nodes' span over its buckets: a span of denormals (nodes 1e-310
  // apart) gave an infinite scale and negative buckets (a crash), one past 1e308 a NaN scale.
  const double span = N.back().s - N.front().s;
  if (N.size() >= 2 && !(std::isfinite(span) && std::isfinite(Buckets / span)))
  {
    std::ostringstream ss;
    ss << "transfer function's control points span " << N.front().s << " .. " << N.back().s
       << (std::isfinite(span) ? ", too close together to tell apart" : ", too wide a span")
       << " in double precision; rescale the data and the transfer function";
    throw Error(ss.str());
  }
  BuildTable();
}

void TransferFunction::BuildTable()
{
  // Locate's table: the interval holding the start of each bucket.
  T0 = N.front().s;
  TScale = N.size() < 2 ? 0.0 : Buckets / (N.back().s - N.front().s);
  Table.assign(Buckets + 1, 0);
  int i = 0;
  for (int k = 0; N.size() >= 2 && k <= Buckets; ++k)
  {
    const double s = T0 + k / TScale;
    while (i + 1 < static_cast<int>(N.size()) && N[i + 1].s <= s)
    {
      ++i;
    }
    Table[k] = i;
  }
  // A bucket is opaque when any interval it touches has extinction at either end; outside the
  // nodes the end values hold.
  auto opaque = [&](int first, int last) {
    for (int j = std::max(first, 0); j <= last && j < static_cast<int>(N.size()); ++j)
    {
      if (N[j].tau > 0)
      {
        return true;
      }
    }
    return false;
  };
  OpaqueBuckets.assign(Buckets + 3, 0);
  for (int j = 0; j < Buckets + 2; ++j)
  {
    bool o;
    if (j == 0)
    {
      o = N.front().tau > 0;
    }
    else if (j == Buckets + 1 || N.size() < 2)
    {
      o = N.back().tau > 0;
    }
    else
    {
      const int k = j - 1;
      o = opaque(Table[k], std::min(Table[k + 1] + 1, static_cast<int>(N.size()) - 1));
    }
    OpaqueBuckets[j + 1] = OpaqueBuckets[j] + (o ? 1 : 0);
  }
  const int n = static_cast<int>(N.size());
  Slopes.assign(static_cast<std::size_t>(std::max(n - 1, 0)), Slope{});
  for (int i = 0; i + 1 < n; ++i)
  {
    const double ds = N[i + 1].s - N[i].s;
    for (int k = 0; k < 3; ++k)
    {
      Slopes[i].rgb[k] = (N[i + 1].rgb[k] - N[i].rgb[k]) / ds;
    }
    Slopes[i].tau = (N[i + 1].tau - N[i].tau) / ds;
  }
  OpaqueIntervals.assign(static_cast<std::size_t>(n + 2), 0);
  for (int i = -1; i < n; ++i)
  {
    const bool o = i < 0 ? N.front().tau > 0 : (i + 1 >= n ? N.back().tau > 0 : N[i].tau > 0 || N[i + 1].tau > 0);
    OpaqueIntervals[i + 2] = OpaqueIntervals[i + 1] + (o ? 1 : 0);
  }
  Bounds.resize(static_cast<std::size_t>(n + 1));
  for (int i = -1; i < n; ++i)
  {
    Bounds[i + 1] = { i < 0 ? -HUGE_VAL : N[i].s, i + 1 < n ? N[i + 1].s : HUGE_VAL };
  }
}

TransferFunction TransferFunction::FromVTK(vtkVolumeProperty* p)
{
  if (!p)
  {
    throw Error("no volume property");
  }
  // One colour channel (SetColor with a vtkPiecewiseFunction) is grey, as VTK's mappers draw it.
  // GetRGBTransferFunction would put VTK's default black-to-white ramp over 0..1024 in its place
  // (a grey of 0.8 on values near 1 drew black) and switch the user's property to three channels,
  // so VTK's own mappers lost the grey function too.
  vtkPiecewiseFunction* gtf = p->GetColorChannels(0) == 1 ? p->GetGrayTransferFunction(0) : nullptr;
  vtkColorTransferFunction* ctf = gtf ? nullptr : p->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = p->GetScalarOpacity(0);
  std::vector<double> s;
  double v[6];
  for (int i = 0; ctf && i < ctf->GetSize(); ++i)
  {
    ctf->GetNodeValue(i, v);
    s.push_back(v[0]);
  }
  for (int i = 0; gtf && i < gtf->GetSize(); ++i)
  {
    gtf->GetNodeValue(i, v);
    s.push_back(v[0]);
  }
  for (int i = 0; otf && i < otf->GetSize(); ++i)
  {
    otf->GetNodeValue(i, v);
    s.push_back(v[0]);
  }
  if (s.empty())
  {
    throw Error("volume property has neither colour nor opacity control points");
  }
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  // A function emptied of its points (RemoveAllPoints) is 0 everywhere, as VTK evaluates it and
  // VTK's mappers draw it: an emptied opacity function hides the volume (it drew it opaque), an
  // emptied colour function draws black (it drew white).
  auto at = [&](double x) {
    Node n{ x, { 1, 1, 1 }, 1.0, 0.0 };
    if (ctf)
    {
      if (ctf->GetSize() > 0)
      {
        ctf->GetColor(x, n.rgb);
      }
      else
      {
        n.rgb[0] = n.rgb[1] = n.rgb[2] = 0.0;
      }
    }
    if (gtf)
    {
      n.rgb[0] = n.rgb[1] = n.rgb[2] = gtf->GetSize() > 0 ? gtf->GetValue(x) : 0.0;
    }
    if (otf)
    {
      n.alpha = otf->GetSize() > 0 ? otf->GetValue(x) : 0.0;
    }
    return n;
  };
  // Between nodes VTK's functions are linear only in RGB with midpoint 0.5 and sharpness 0; other
  // colour spaces (Diverging, Lab, HSV: ParaView's defaults), midpoints, sharpness and a log
  // scale bend them. Such intervals are halved, up to 256 pieces, until the linear pieces are
  // within 1/500 of VTK's values at their quarter points.
  std::vector<Node> nodes;
  std::function<void(const Node&, const Node&, int)> refine = [&](const Node& a, const Node& b, int depth) {
    bool bent = false;
    Node q[3];
    for (int k = 0; k < 3; ++k)
    {
      const double f = 0.25 * (k + 1);
      q[k] = at(a.s + f * (b.s - a.s));
      for (int c = 0; c < 3 && !bent; ++c)
      {
        bent = std::fabs(q[k].rgb[c] - (a.rgb[c] + f * (b.rgb[c] - a.rgb[c]))) > 2e-3;
      }
      bent = bent || std::fabs(q[k].alpha - (a.alpha + f * (b.alpha - a.alpha))) > 2e-3;
    }
    if (!bent || depth >= 8)
    {
      return;
    }
    refine(a, q[1], depth + 1); // q[1]: the midpoint, already evaluated
    nodes.push_back(q[1]);
    refine(q[1], b, depth + 1);
  };
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    const Node n = at(s[i]);
    if (i > 0)
    {
      const Node prev = nodes.back(); // a copy: refine appends to nodes
      refine(prev, n, 0);
    }
    nodes.push_back(n);
  }
  return TransferFunction(std::move(nodes), p->GetScalarOpacityUnitDistance(0));
}

void TransferFunction::ToVTK(vtkVolumeProperty* p) const
{
  vtkNew<vtkColorTransferFunction> ctf;
  vtkNew<vtkPiecewiseFunction> otf;
  for (const Node& n : N)
  {
    ctf->AddRGBPoint(n.s, n.rgb[0], n.rgb[1], n.rgb[2]);
    otf->AddPoint(n.s, n.alpha);
  }
  p->SetColor(0, ctf);
  p->SetScalarOpacity(0, otf);
  p->SetScalarOpacityUnitDistance(0, Unit);
  p->SetInterpolationTypeToLinear();
}

std::vector<std::string> TransferFunction::PresetNames()
{
  return { "auto", "ct-skin-bone", "ct-bone", "grey-ramp", "constant", "labels" };
}

namespace
{
double UnitDistanceFor(bool hu, double h)
{
  if (!(h > 0.0) || !std::isfinite(h))
  {
    return 1.0;
  }
  return hu && h >= 0.1 && h <= 10.0 ? 1.0 : h;
}

// Are samples whose range looks like Hounsfield units a CT's? Scanners store whole units, and a
// CT, or a mesh reduced from one (fitted values, not whole), has air in or around it; a
// simulation field that spans -1000 .. 1000 (a pressure, a velocity component) has neither: in
// skin-and-bone colours it looked like an anatomy. Measured: the CT heads are int16 with 58% of
// their voxels within 100 HU of air (-1000), their reduced meshes 18-29% of their vertices; a
// float pressure field of -997 .. 997, 0.8%. Up to ~200k evenly spread samples are looked at.
template <class Value>
bool SamplesLookLikeCT(long long n, bool integerType, Value&& value)
{
  const long long step = std::max(1LL, n / 200000);
  long long seen = 0, air = 0;
  bool whole = true;
  for (long long i = 0; i < n; i += step)
  {
    const double v = value(i);
    whole = whole && (integerType || v == std::floor(v));
    air += v >= -1100.0 && v <= -900.0;
    ++seen;
  }
  return seen > 0 && (whole || air >= 0.05 * static_cast<double>(seen));
}
} // namespace

double TransferFunction::PresetUnitDistance(double lo, double hi, double h)
{
  return UnitDistanceFor(LooksLikeHU(lo, hi), h);
}

double TransferFunction::SampleSpacing(vtkDataSet* data, const TetMesh* mesh)
{
  if (auto* image = vtkImageData::SafeDownCast(data))
  {
    return MeanVoxelSpacing(image->GetDimensions(), image->GetSpacing());
  }
  if (vtkDataArray* a = data->GetFieldData() ? data->GetFieldData()->GetArray("source_spacing") : nullptr)
  {
    const double h = a->GetNumberOfTuples() > 0 ? a->GetComponent(0, 0) : 0.0;
    if (h > 0.0 && std::isfinite(h))
    {
      return h;
    }
  }
  if (mesh && mesh->NumberOfPoints() > 0)
  {
    const Vec3 e = mesh->Bounds().hi - mesh->Bounds().lo;
    const double extent[3] = { e.x, e.y, e.z };
    return MeanSpacing(extent, static_cast<double>(mesh->NumberOfPoints()));
  }
  double b[6];
  data->GetBounds(b);
  const double extent[3] = { b[1] - b[0], b[3] - b[2], b[5] - b[4] };
  return MeanSpacing(extent, static_cast<double>(data->GetNumberOfPoints()));
}

TransferFunction TransferFunction::PresetFor(const std::string& name, vtkDataSet* data, double lo, double hi,
  const TetMesh* mesh)
{
  bool hu = LooksLikeHU(lo, hi);
  vtkDataArray* a = data && data->GetPointData() ? data->GetPointData()->GetScalars() : nullptr;
  if (hu && mesh && mesh->NumberOfPoints() > 0)
  {
    hu = SamplesLookLikeCT(static_cast<long long>(mesh->NumberOfPoints()), false,
      [&](long long i) { return mesh->Scalars()[static_cast<std::size_t>(i)]; });
  }
  else if (hu && a && a->GetNumberOfComponents() == 1 && a->GetNumberOfTuples() > 0 && a->GetRange()[0] == lo &&
    a->GetRange()[1] == hi) // the samples drawn (not another array's, nor a vector's magnitude)
  {
    const int type = a->GetDataType();
    hu = SamplesLookLikeCT(static_cast<long long>(a->GetNumberOfTuples()), type != VTK_FLOAT && type != VTK_DOUBLE,
      [&](long long i) { return a->GetComponent(i, 0); });
  }
  const double unit = UnitDistanceFor(hu, SampleSpacing(data, mesh));
  if (name == "auto" && !hu)
  {
    return DataTransferFunction(StatisticsFor(data, lo, hi, mesh), unit);
  }
  return Make(name, lo, hi, unit, hu);
}

TransferFunction TransferFunction::MaximumIntensityFor(vtkDataSet* data, double lo, double hi, const TetMesh* mesh)
{
  return DataTransferFunction(StatisticsFor(data, lo, hi, mesh), UnitDistanceFor(LooksLikeHU(lo, hi),
    SampleSpacing(data, mesh)), TransferFunctionUse::MaximumIntensity);
}

TransferFunction TransferFunction::Preset(const std::string& name, double lo, double hi, double unitDistance)
{
  return Make(name, lo, hi, unitDistance, LooksLikeHU(lo, hi));
}

namespace
{
// A categorical table for label maps: one node per integer label in [lo, hi] (the first 512), in
// the ten colours of Tableau's palette in turn, each half opaque per unit distance. A label
// mesh's tets hold their label exactly, so no two labels' colours blend.
std::vector<TransferFunction::Node> LabelNodes(double lo, double hi)
{
  static const double palette[10][3] = { { 0.12, 0.47, 0.71 }, { 1.0, 0.5, 0.05 }, { 0.17, 0.63, 0.17 },
    { 0.84, 0.15, 0.16 }, { 0.58, 0.4, 0.74 }, { 0.55, 0.34, 0.29 }, { 0.89, 0.47, 0.76 }, { 0.5, 0.5, 0.5 },
    { 0.74, 0.74, 0.13 }, { 0.09, 0.75, 0.81 } };
  std::vector<TransferFunction::Node> n;
  const double first = std::ceil(lo), last = std::min(std::floor(hi), first + 511);
  for (double k = first; k <= last; ++k)
  {
    const auto& c = palette[static_cast<long long>(std::fabs(k)) % 10];
    n.push_back({ k, { c[0], c[1], c[2] }, 0.5, 0 });
  }
  if (n.size() < 2) // no integer or one in the range: its colour over all of it
  {
    const auto& c = palette[n.empty() ? 0 : static_cast<long long>(std::fabs(first)) % 10];
    n = { { lo, { c[0], c[1], c[2] }, 0.5, 0 }, { hi, { c[0], c[1], c[2] }, 0.5, 0 } };
  }
  return n;
}
} // namespace

TransferFunction TransferFunction::Make(const std::string& name, double lo, double hi, double unitDistance, bool hu)
{
  if (!(hi > lo))
  {
    // A constant field: its value in the middle of the preset, so it shows as a uniform haze
    // rather than at the preset's clear end.
    const double w = std::max(1.0, 1e-3 * std::fabs(lo));
    lo -= w;
    hi += w;
  }
  // CT presets in Hounsfield units when the data look like CT, else at fractions of the range.
  auto at = [&](double h, double frac) { return hu ? h : lo + frac * (hi - lo); };
  // The last node: at the data's maximum, or 1 HU past the one before when CT stops below it.
  auto top = [&](double h) { return hu ? std::max(hi, h + 1) : hi; };
  // "auto": the skin-and-bone preset on CT, a grey ramp on anything else (MRI, simulations),
  // where the CT presets' opaque top fifth of the range draws an opaque white blob.
  const std::string kind = name == "auto" ? (hu ? "ct-skin-bone" : "grey-ramp") : name;
  std::vector<Node> n;
  if (kind == "ct-skin-bone")
  {
    n = { { lo, { 0, 0, 0 }, 0.0, 0 }, { at(-600, 0.15), { 0.75, 0.45, 0.3 }, 0.0, 0 },
      { at(-450, 0.2), { 0.9, 0.6, 0.45 }, 0.12, 0 }, { at(-300, 0.25), { 0.9, 0.65, 0.5 }, 0.0, 0 },
      { at(200, 0.45), { 0.95, 0.85, 0.7 }, 0.0, 0 }, { at(450, 0.55), { 1.0, 0.95, 0.85 }, 0.25, 0 },
      { at(1200, 0.8), { 1.0, 1.0, 0.95 }, 0.7, 0 }, { top(at(1200, 0.8)), { 1, 1, 1 }, 0.8, 0 } };
  }
  else if (kind == "ct-bone")
  {
    n = { { lo, { 0, 0, 0 }, 0.0, 0 }, { at(200, 0.45), { 0.9, 0.8, 0.65 }, 0.0, 0 },
      { at(500, 0.6), { 1.0, 0.95, 0.85 }, 0.3, 0 }, { top(at(500, 0.6)), { 1, 1, 1 }, 0.8, 0 } };
  }
  else if (kind == "grey-ramp")
  {
    n = { { lo, { 0, 0, 0 }, 0.0, 0 }, { hi, { 1, 1, 1 }, 0.2, 0 } };
  }
  else if (kind == "constant")
  {
    n = { { lo, { 0, 0, 0 }, 0.05, 0 }, { hi, { 1, 1, 1 }, 0.05, 0 } };
  }
  else if (kind == "labels")
  {
    n = LabelNodes(lo, hi);
  }
  else
  {
    std::string all;
    for (const auto& p : PresetNames())
    {
      all += (all.empty() ? "" : ", ") + p;
    }
    throw Error("unknown transfer-function preset '" + name + "' (known: " + all + ")");
  }
  return TransferFunction(std::move(n), unitDistance);
}

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

double TransferFunction::Alpha(double s) const
{
  const int i = Locate(s);
  if (i < 0 || i + 1 >= static_cast<int>(N.size()))
  {
    return (i < 0 ? N.front() : N.back()).alpha;
  }
  const Node &a = N[i], &b = N[i + 1];
  return a.alpha + (s - a.s) / (b.s - a.s) * (b.alpha - a.alpha);
}
} // namespace art
