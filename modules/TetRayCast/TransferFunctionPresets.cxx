// TransferFunction's presets: the named colour maps, whether a data set holds Hounsfield units
// (a CT's) and the unit distance that suits its sample spacing.
#include "TransferFunction.h"
#include "DataTransferFunction.h"

#include "TetMesh.h"

#include "Error.h"
#include "MeanSpacing.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>

namespace art
{
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

const double* TransferFunction::CategoricalColour(long long k)
{
  static constexpr double palette[10][3] = { { 0.122, 0.467, 0.706 }, { 1.000, 0.498, 0.055 },
    { 0.173, 0.627, 0.173 }, { 0.839, 0.153, 0.157 }, { 0.580, 0.404, 0.741 }, { 0.549, 0.337, 0.294 },
    { 0.890, 0.467, 0.761 }, { 0.498, 0.498, 0.498 }, { 0.737, 0.741, 0.133 }, { 0.090, 0.745, 0.812 } };
  return palette[(k % 10 + 10) % 10];
}

namespace
{
// A categorical table for label maps: one node per integer label in [lo, hi] (the first 512), in
// the ten colours of Tableau's palette in turn, each half opaque per unit distance. A label
// mesh's tets hold their label exactly, so no two labels' colours blend.
std::vector<TransferFunction::Node> LabelNodes(double lo, double hi)
{
  std::vector<TransferFunction::Node> n;
  const double first = std::ceil(lo), last = std::min(std::floor(hi), first + 511);
  for (double k = first; k <= last; ++k)
  {
    const double* c = TransferFunction::CategoricalColour(static_cast<long long>(std::fabs(k)));
    n.push_back({ k, { c[0], c[1], c[2] }, 0.5, 0 });
  }
  if (n.size() < 2) // no integer or one in the range: its colour over all of it
  {
    const double* c = TransferFunction::CategoricalColour(n.empty() ? 0 : static_cast<long long>(std::fabs(first)));
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
} // namespace art
