#include "SourceStatistics.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace art
{
namespace
{
void Put(vtkFieldData* fd, const char* name, const double* v, int n, int components = 1)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(n / components);
  for (int i = 0; i < n; ++i)
  {
    a->SetValue(i, v[i]);
  }
  fd->RemoveArray(name);
  fd->AddArray(a);
}

bool Finite(vtkDataArray* a)
{
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    if (!std::isfinite(a->GetComponent(i / a->GetNumberOfComponents(), i % a->GetNumberOfComponents())))
    {
      return false;
    }
  }
  return true;
}
} // namespace

void WriteSourceStatistics(vtkFieldData* fd, const ScalarStatistics& s)
{
  const double window[2] = { s.windowLow, s.windowHigh };
  Put(fd, "source_window", window, 2, 2);
  Put(fd, "scalar_range_min", &s.lo, 1);
  Put(fd, "scalar_range_max", &s.hi, 1);
  fd->RemoveArray("source_background_top");
  if (s.hasBackground)
  {
    Put(fd, "source_background_top", &s.backgroundTop, 1);
  }
  fd->RemoveArray("source_label_values");
  if (s.labels)
  {
    Put(fd, "source_label_values", s.labelValues.data(), static_cast<int>(s.labelValues.size()));
  }
}

bool ReadSourceStatistics(vtkFieldData* fd, ScalarStatistics& s)
{
  vtkDataArray* w = fd ? fd->GetArray("source_window") : nullptr;
  vtkDataArray* lo = fd ? fd->GetArray("scalar_range_min") : nullptr;
  vtkDataArray* hi = fd ? fd->GetArray("scalar_range_max") : nullptr;
  if (!w || !lo || !hi || w->GetNumberOfValues() != 2 || lo->GetNumberOfValues() != 1 ||
    hi->GetNumberOfValues() != 1 || !Finite(w) || !Finite(lo) || !Finite(hi))
  {
    return false;
  }
  ScalarStatistics r;
  r.samples = 1;
  r.lo = lo->GetComponent(0, 0);
  r.hi = hi->GetComponent(0, 0);
  r.windowLow = w->GetComponent(0, 0);
  r.windowHigh = w->GetComponent(0, 1);
  if (!(r.lo <= r.windowLow && r.windowLow <= r.windowHigh && r.windowHigh <= r.hi))
  {
    return false;
  }
  if (vtkDataArray* b = fd->GetArray("source_background_top"))
  {
    if (b->GetNumberOfValues() == 1 && Finite(b))
    {
      r.hasBackground = true;
      r.backgroundTop = b->GetComponent(0, 0);
    }
  }
  if (vtkDataArray* l = fd->GetArray("source_label_values"))
  {
    if (l->GetNumberOfComponents() == 1 && l->GetNumberOfTuples() >= 2 &&
      l->GetNumberOfTuples() <= ScalarStatistics::MaxLabels && Finite(l))
    {
      r.labels = true;
      for (vtkIdType i = 0; i < l->GetNumberOfTuples(); ++i)
      {
        r.labelValues.push_back(l->GetComponent(i, 0));
      }
    }
  }
  s = std::move(r);
  return true;
}

bool StillTheSource(double sourceLo, double sourceHi, long long n, const std::function<double(long long)>& value)
{
  if (n <= 0 || !(sourceHi >= sourceLo))
  {
    return false;
  }
  const long long step = std::max(1LL, n / 65536);
  std::vector<double> v;
  for (long long i = 0; i < n; i += step)
  {
    v.push_back(value(i));
  }
  const auto at = [&](double q) {
    auto k = v.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), k, v.end());
    return *k;
  };
  const double slack = 0.25 * (sourceHi - sourceLo);
  const double lo = at(0.02), hi = at(0.98);
  return lo >= sourceLo - slack && hi <= sourceHi + slack;
}

ScalarStatistics SummarizeArray(vtkDataArray* a)
{
  const long long n = a ? static_cast<long long>(a->GetNumberOfTuples()) : 0;
  if (n == 0)
  {
    return {};
  }
  const int type = a->GetDataType();
  bool integers = type != VTK_FLOAT && type != VTK_DOUBLE;
  for (long long i = 0; !integers && i < n; ++i)
  {
    const double v = a->GetComponent(i, 0);
    if (v != std::floor(v) && !std::isnan(v))
    {
      break;
    }
    integers = i + 1 == n;
  }
  return Summarize(n, [a](long long i) { return a->GetComponent(i, 0); }, integers);
}
} // namespace art
