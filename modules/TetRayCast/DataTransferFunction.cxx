#include "DataTransferFunction.h"

#include "SourceStatistics.h"
#include "TetMesh.h"

#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>

namespace art
{
namespace
{
using Node = TransferFunction::Node;

// Each label constant over the half-way points to its neighbours; the one background label (0, or
// the lowest when it is the background) transparent.
std::vector<Node> LabelNodes(const ScalarStatistics& s)
{
  const std::vector<double>& L = s.labelValues;
  const bool zero = std::find(L.begin(), L.end(), 0.0) != L.end();
  const double background = zero ? 0.0 : (s.hasBackground ? L.front() : NAN);
  std::vector<Node> n;
  int colour = 0;
  for (std::size_t i = 0; i < L.size(); ++i)
  {
    const double below = i == 0 ? L[i] - 0.5 : 0.5 * (L[i - 1] + L[i]);
    const double above = i + 1 == L.size() ? L[i] + 0.5 : 0.5 * (L[i] + L[i + 1]);
    const double eps = 1e-3 * std::min(L[i] - below, above - L[i]);
    Node a{ below + eps, { 0, 0, 0 }, 0.0, 0 };
    if (L[i] != background)
    {
      const double* c = TransferFunction::CategoricalColour(colour++);
      a = Node{ below + eps, { c[0], c[1], c[2] }, LabelOpacity, 0 };
    }
    Node b = a;
    b.s = above - eps;
    n.push_back(a);
    n.push_back(b);
  }
  return n;
}

// Transparent up to the window's start (the background's top when higher), then a grey ramp
// whose opacity rises slowly at first (a tenth of the top at mid-window), so that dim tissue
// and noise stay clear and the bright structures show.
std::vector<Node> RampNodes(const ScalarStatistics& s, TransferFunctionUse use)
{
  const double start = std::max(s.windowLow, s.hasBackground ? s.backgroundTop : s.lo);
  double top = std::max(s.windowHigh, start);
  if (!(top > start))
  {
    top = std::max(s.hi, start + std::max(1.0, std::fabs(start)) * 1e-3);
  }
  std::vector<Node> n;
  n.push_back({ std::min(s.lo, start), { 0, 0, 0 }, 0.0, 0 });
  if (use == TransferFunctionUse::MaximumIntensity)
  {
    // The pixel is colour x opacity at the maximum: white with opacity linear over the window
    // draws the window as a linear grey ramp, its top white.
    n.push_back({ start, { 1, 1, 1 }, 0.0, 0 });
    n.push_back({ top, { 1, 1, 1 }, 1.0, 0 });
  }
  else
  {
    n.push_back({ start, { 0, 0, 0 }, 0.0, 0 });
    n.push_back({ 0.5 * (start + top), { 0.5, 0.5, 0.5 }, 0.1 * DataRampOpacity, 0 });
    n.push_back({ top, { 1, 1, 1 }, DataRampOpacity, 0 });
  }
  if (s.hi > top)
  {
    Node last = n.back();
    last.s = s.hi;
    n.push_back(last);
  }
  return n;
}
} // namespace

TransferFunction DataTransferFunction(const ScalarStatistics& s, double unitDistance, TransferFunctionUse use)
{
  if (s.labels && use == TransferFunctionUse::EmissionAbsorption)
  {
    return TransferFunction(LabelNodes(s), unitDistance);
  }
  return TransferFunction(RampNodes(s, use), unitDistance);
}

ScalarStatistics StatisticsFor(vtkDataSet* data, double lo, double hi, const TetMesh* mesh)
{
  ScalarStatistics s;
  vtkDataArray* a = data && data->GetPointData() ? data->GetPointData()->GetScalars() : nullptr;
  if (data && ReadSourceStatistics(data->GetFieldData(), s))
  {
    // The values drawn: the mesh's (built from the data), else the data's point scalars.
    const bool still = mesh && mesh->NumberOfPoints() > 0
      ? StillTheSource(s.lo, s.hi, static_cast<long long>(mesh->NumberOfPoints()),
          [mesh](long long i) { return mesh->Scalars()[static_cast<std::size_t>(i)]; })
      : a && StillTheSource(s.lo, s.hi, a->GetNumberOfTuples(), [a](long long i) { return a->GetComponent(i, 0); });
    if (still)
    {
      return s;
    }
  }
  if (a && a->GetNumberOfTuples() > 0 && a->GetRange(0)[0] == lo && a->GetRange(0)[1] == hi)
  {
    return SummarizeArray(a);
  }
  if (mesh && mesh->NumberOfPoints() > 0)
  {
    const std::vector<double>& v = mesh->Scalars();
    return Summarize(static_cast<long long>(v.size()), [&v](long long i) { return v[i]; }, false);
  }
  s = ScalarStatistics{};
  s.lo = s.windowLow = lo;
  s.hi = s.windowHigh = hi;
  s.samples = 1;
  return s;
}
} // namespace art
