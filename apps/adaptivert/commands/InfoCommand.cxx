// adaptivert info FILE...: what a volume, surface or mesh holds.
#include "ArrayChoice.h"
#include "cli/NumberFormat.h"
#include "cli/Command.h"
#include "AtomicFile.h"
#include "DataLoader.h"
#include "Error.h"
#include "ValueMagnitude.h"
#include "cli/Json.h"
#include "SourceStatistics.h"
#include "cli/LoadOptions.h"
#include "VolumePlacement.h"

#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <map>

namespace
{
using cli::Grouped;

// printf into a string, so the same code serves the text and the --json output.
void Out(std::string& text, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
void Out(std::string& text, const char* fmt, ...)
{
  char buf[1024];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  text += buf;
}

// "lo SEP hi" with the fewest digits (at least six) that tell them apart: 1000 + 1e-9 variations
// printed as "1000 .. 1000".
std::string Range(double lo, double hi, const char* sep)
{
  char a[40], b[40];
  for (int digits = 6; digits <= 17; ++digits)
  {
    std::snprintf(a, sizeof a, "%.*g", digits, lo);
    std::snprintf(b, sizeof b, "%.*g", digits, hi);
    if (lo == hi || std::string(a) != b)
    {
      break;
    }
  }
  return std::string(a) + sep + b;
}

std::string Bounds(vtkDataSet* ds)
{
  double b[6];
  ds->GetBounds(b);
  char s[200];
  // Ten digits: data 1e7 away from the origin printed as "x [1e+07, 1e+07]" with six.
  std::snprintf(s, sizeof s, "x [%.10g, %.10g]  y [%.10g, %.10g]  z [%.10g, %.10g]", b[0], b[1], b[2], b[3], b[4], b[5]);
  return s;
}

// NaN and infinite values of a float or double array (VTK's ranges leave them out; other types
// hold none).
struct NonFinite
{
  long long nan = 0, inf = 0;
};
NonFinite CountNonFinite(vtkDataArray* a)
{
  NonFinite c;
  auto count = [&](const auto* v, vtkIdType n) {
    for (vtkIdType i = 0; i < n; ++i)
    {
      c.nan += std::isnan(v[i]) ? 1 : 0;
      c.inf += std::isinf(v[i]) ? 1 : 0;
    }
  };
  if (auto* f = vtkFloatArray::SafeDownCast(a))
  {
    count(f->GetPointer(0), f->GetNumberOfValues());
  }
  else if (auto* d = vtkDoubleArray::SafeDownCast(a))
  {
    count(d->GetPointer(0), d->GetNumberOfValues());
  }
  return c;
}

std::string ArrayList(vtkFieldData* fd)
{
  std::string s;
  for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* a = fd->GetAbstractArray(i);
    s += std::string(i ? ", " : "") + (a->GetName() ? a->GetName() : "(unnamed)");
    if (auto* da = vtkDataArray::SafeDownCast(a))
    {
      double r[2];
      da->GetRange(r, -1);
      char b[160];
      // VTK's range leaves NaN out: a masked field looked whole, and render then refused it.
      const NonFinite nf = CountNonFinite(da);
      const long long bad = nf.nan + nf.inf;
      std::snprintf(b, sizeof b, " [%s x%d, %s%s%s]", da->GetDataTypeAsString(), da->GetNumberOfComponents(),
        Range(r[0], r[1], "..").c_str(), bad > 0 ? ", NaN or infinite: " : "", bad > 0 ? Grouped(bad).c_str() : "");
      s += b;
    }
  }
  return s.empty() ? "none" : s;
}

// Medical formats place voxels in LPS patient coordinates: name where the axes point, and which
// NIfTI transform placed them (a flipped or turned file is otherwise easy to miss).
void Orientation(const std::string& path, vtkImageData* img, std::string& text, cli::Json& j)
{
  const std::string e = art::LowerExtension(path);
  const bool nifti = e == ".nii" || e == ".nii.gz";
  if (!(nifti || e == ".mha" || e == ".mhd" || e == ".nrrd" || e == ".nhdr" || std::filesystem::is_directory(path)))
  {
    return;
  }
  std::string codes = art::AxisCodes(img);
  art::NiftiPlacementInfo placement;
  if (nifti)
  {
    // VTK may read a NIfTI file's slices last first; other tools (fslhd, nibabel) name the
    // file's own axes.
    placement = art::NiftiPlacement(path);
    const std::string from = "LRPAIS", to = "RLAPSI";
    codes[2] = placement.SlicesReversed ? to[from.find(codes[2])] : codes[2];
  }
  std::string words;
  for (char c : codes)
  {
    const std::string letters = "LRPAIS";
    const char* names[6] = { "left", "right", "posterior", "anterior", "inferior", "superior" };
    words += (words.empty() ? "" : ", ") + std::string(names[letters.find(c)]);
  }
  if (!nifti || placement.Placed) // a NIfTI file without qform or sform says nothing of anatomy
  {
    Out(text, "  orientation  %s (%si, j, k toward %s; world x, y, z = left, posterior, superior)\n", codes.c_str(),
      nifti ? "the file's " : "", words.c_str());
    j.Set("orientation", codes);
  }
  if (nifti)
  {
    Out(text, "  placed by    NIfTI %s%s\n", placement.How.c_str(), placement.SlicesReversed ? "; slices read last first" : "");
    j.Set("nifti_placement", placement.How).Set("slices_reversed", placement.SlicesReversed);
    if (placement.TimePoints > 1)
    {
      // A 4-D series (fMRI, DWI) loads its first volume only: say so.
      Out(text, "  volumes      %lld in the file (dim[4..7]); the first is loaded\n", placement.TimePoints);
      j.Set("volumes_in_file", placement.TimePoints);
    }
  }
}

// What render and reduce would refuse in the scalars: non-finite values, magnitudes past double.
void DescribeScalarProblems(vtkDataArray* s, const double r[2], std::string& text, cli::Json& j)
{
  // NaN voxels (a masked MRI map, a statistics volume) are left out of VTK's range: the range
  // alone looked fine, and render and reduce then refused the volume.
  const auto [nan, inf] = CountNonFinite(s);
  if (nan + inf > 0)
  {
    Out(text, "  non-finite   %s NaN and %s infinite values (render and reduce need finite voxels: replace them first, e.g. with numpy.nan_to_num)\n",
      Grouped(nan).c_str(), Grouped(inf).c_str());
  }
  j.Set("nan_values", nan).Set("infinite_values", inf);
  // Values of 1e300 or 1e-310: render and reduce refuse them; say so where the range is shown.
  if (s->GetNumberOfComponents() == 1 && std::isfinite(r[0]) && std::isfinite(r[1]))
  {
    try
    {
      art::RequireComputableRange(r[0], r[1], {});
    }
    catch (const art::Error& e)
    {
      Out(text, "  magnitude    %s\n", e.problem().c_str());
      j.Set("magnitude_problem", e.problem());
    }
  }
}

// A volume: its grid, placement, scalars (their problems: NaN, magnitudes past double), arrays.
// What the default transfer function is made from (art::ScalarStatistics): the background it
// leaves clear, the window its ramp spans, the labels it colours.
void DescribeStatistics(const art::ScalarStatistics& st, std::string& text, cli::Json& j)
{
  std::string line = "window " + Range(st.windowLow, st.windowHigh, " .. ") + " (1st-99.5th percentile";
  line += st.hasBackground ? " above the background " + Range(st.lo, st.backgroundTop, " .. ") + ")" : ", no background)";
  if (st.labels)
  {
    line += "; labels:";
    for (double v : st.labelValues)
    {
      char one[32];
      std::snprintf(one, sizeof one, " %g", v);
      line += one;
    }
  }
  Out(text, "  statistics   %s\n", line.c_str());
  j.Set("window", std::vector<double>{ st.windowLow, st.windowHigh });
  if (st.hasBackground)
  {
    j.Set("background_top", st.backgroundTop);
  }
  if (st.labels)
  {
    j.Set("labels", st.labelValues);
  }
}

void DescribeVolume(const std::string& path, vtkImageData* img, std::string& text, cli::Json& j)
{
  int d[3];
  img->GetDimensions(d);
  const double* sp = img->GetSpacing();
  const double* o = img->GetOrigin();
  vtkDataArray* s = img->GetPointData()->GetScalars();
  // A vector's range is its magnitude's (as ParaView gives it): component 0's said nothing of it.
  double r[2];
  s->GetRange(r, s->GetNumberOfComponents() > 1 ? -1 : 0);
  Out(text, "  dimensions   %d x %d x %d (%s voxels)\n", d[0], d[1], d[2],
    Grouped(static_cast<long long>(d[0]) * d[1] * d[2]).c_str());
  Out(text, "  spacing      %g x %g x %g\n", sp[0], sp[1], sp[2]);
  Out(text, "  origin       %.10g, %.10g, %.10g\n", o[0], o[1], o[2]);
  const double* dm = img->GetDirectionMatrix()->GetData();
  if (!img->GetDirectionMatrix()->IsIdentity())
  {
    // The axes turned or mirrored: otherwise only the bounds would show it.
    // + 0.0 prints -0 as 0.
    Out(text, "  direction    [%g %g %g; %g %g %g; %g %g %g]\n", dm[0] + 0.0, dm[1] + 0.0, dm[2] + 0.0, dm[3] + 0.0,
      dm[4] + 0.0, dm[5] + 0.0, dm[6] + 0.0, dm[7] + 0.0, dm[8] + 0.0);
    j.Set("direction", std::vector<double>(dm, dm + 9));
  }
  Out(text, "  bounds       %s\n", Bounds(img).c_str());
  Orientation(path, img, text, j);
  Out(text, "  scalars      %s, %d component%s, %srange %s%s\n", s->GetDataTypeAsString(),
    s->GetNumberOfComponents(), s->GetNumberOfComponents() > 1 ? "s" : "",
    s->GetNumberOfComponents() > 1 ? "magnitude " : "", Range(r[0], r[1], " .. ").c_str(),
    s->GetNumberOfComponents() > 1 ? (" (--array " + art::ComponentHint(s) + ")").c_str() : "");
  DescribeScalarProblems(s, r, text, j);
  if (s->GetNumberOfComponents() == 1 && std::isfinite(r[0]) && std::isfinite(r[1]))
  {
    DescribeStatistics(art::SummarizeArray(s), text, j);
  }
  Out(text, "  point data   %s%s\n", ArrayList(img->GetPointData()).c_str(),
    img->GetPointData()->GetNumberOfArrays() > 1 ? " (--array picks one)" : "");
  if (img->GetCellData()->GetNumberOfArrays() > 0)
  {
    Out(text, "  cell data    %s\n", ArrayList(img->GetCellData()).c_str());
  }
  std::vector<std::string> names;
  for (int i = 0; i < img->GetPointData()->GetNumberOfArrays(); ++i)
  {
    const char* n = img->GetPointData()->GetArrayName(i);
    names.push_back(n ? n : "");
  }
  j.Set("arrays", names).Set("scalars_name", s->GetName() ? s->GetName() : "");
  if (auto* frame = vtkStringArray::SafeDownCast(img->GetFieldData()->GetAbstractArray("Frame")))
  {
    Out(text, "  frame        %s (--frame %s)\n", frame->GetValue(0).c_str(),
      frame->GetValue(0) == "VTK reader" ? "vtk: as VTK's readers and ParaView place the voxels" : "patient: LPS patient coordinates");
    j.Set("frame", frame->GetValue(0));
  }
  if (auto* m = vtkDoubleArray::SafeDownCast(img->GetFieldData()->GetArray("IndexToWorld")))
  {
    j.Set("index_to_world", std::vector<double>(m->GetPointer(0), m->GetPointer(0) + 16));
  }
  j.Set("dimensions", std::vector<double>{ double(d[0]), double(d[1]), double(d[2]) })
    .Set("spacing", std::vector<double>(sp, sp + 3))
    .Set("origin", std::vector<double>(o, o + 3))
    .Set("scalar_type", s->GetDataTypeAsString())
    .Set("components", s->GetNumberOfComponents())
    .Set("range", std::vector<double>{ r[0], r[1] });
}

// A surface: its triangles, counting those in strips and polygons alike.
void DescribeSurface(vtkPolyData* pd, std::string& text, cli::Json& j)
{
  long long tris = 0, other = 0, stripTris = 0;
  vtkCellArray* polys = pd->GetPolys();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    (polys->GetCellSize(c) == 3 ? tris : other)++;
  }
  // A strip of n points holds n - 2 triangles (a .vtp of strips showed 0 triangles).
  vtkCellArray* strips = pd->GetStrips();
  for (vtkIdType c = 0; c < strips->GetNumberOfCells(); ++c)
  {
    stripTris += std::max<vtkIdType>(0, strips->GetCellSize(c) - 2);
  }
  Out(text, "  points       %s\n", Grouped(pd->GetNumberOfPoints()).c_str());
  Out(text, "  polygons     %s (%s triangles, %s other)\n", Grouped(pd->GetNumberOfPolys()).c_str(),
    Grouped(tris).c_str(), Grouped(other).c_str());
  if (pd->GetNumberOfStrips())
  {
    Out(text, "  strips       %s (%s triangles)\n", Grouped(pd->GetNumberOfStrips()).c_str(), Grouped(stripTris).c_str());
  }
  Out(text, "  triangles    %s\n", Grouped(tris + stripTris).c_str());
  if (pd->GetNumberOfLines() || pd->GetNumberOfVerts())
  {
    Out(text, "  also         %s lines, %s vertices\n", Grouped(pd->GetNumberOfLines()).c_str(),
      Grouped(pd->GetNumberOfVerts()).c_str());
  }
  Out(text, "  bounds       %s\n", Bounds(pd).c_str());
  Out(text, "  point data   %s\n", ArrayList(pd->GetPointData()).c_str());
  Out(text, "  cell data    %s\n", ArrayList(pd->GetCellData()).c_str()); // face colours, labels
  j.Set("points", static_cast<long long>(pd->GetNumberOfPoints()))
    .Set("polygons", static_cast<long long>(pd->GetNumberOfPolys()))
    .Set("triangles", tris + stripTris)
    .Set("triangles_in_polygons", tris)
    .Set("triangles_in_strips", stripTris)
    .Set("strips", static_cast<long long>(pd->GetNumberOfStrips()));
}

// A mesh: its cells by type and its arrays.
void DescribeMesh(vtkUnstructuredGrid* ug, std::string& text, cli::Json& j)
{
  std::map<std::string, long long> types;
  for (vtkIdType c = 0; c < ug->GetNumberOfCells(); ++c)
  {
    types[vtkCellTypes::GetClassNameFromTypeId(ug->GetCellType(c))]++;
  }
  Out(text, "  points       %s\n", Grouped(ug->GetNumberOfPoints()).c_str());
  Out(text, "  cells        %s\n", Grouped(ug->GetNumberOfCells()).c_str());
  cli::Json jt;
  for (const auto& [name, n] : types)
  {
    Out(text, "    %-12s %s\n", name.c_str(), Grouped(n).c_str());
    jt.Set(name, n);
  }
  Out(text, "  bounds       %s\n", Bounds(ug).c_str());
  Out(text, "  point data   %s\n", ArrayList(ug->GetPointData()).c_str());
  Out(text, "  cell data    %s\n", ArrayList(ug->GetCellData()).c_str());
  Out(text, "  field data   %s\n", ArrayList(ug->GetFieldData()).c_str());
  j.Set("points", static_cast<long long>(ug->GetNumberOfPoints()))
    .Set("cells", static_cast<long long>(ug->GetNumberOfCells()))
    .Set("cell_types", jt);
}

cli::Json Describe(const std::string& path, vtkDataObject* obj, art::DataKind kind, std::string& text)
{
  cli::Json j;
  j.Set("file", path).Set("kind", art::KindName(kind));
  auto* ds = vtkDataSet::SafeDownCast(obj);
  double b[6];
  ds->GetBounds(b);
  j.Set("bounds", std::vector<double>(b, b + 6));
  Out(text, "%s: %s\n", path.c_str(), art::KindName(kind));
  if (auto* img = vtkImageData::SafeDownCast(obj))
  {
    DescribeVolume(path, img, text, j);
  }
  else if (auto* pd = vtkPolyData::SafeDownCast(obj))
  {
    DescribeSurface(pd, text, j);
  }
  else if (auto* ug = vtkUnstructuredGrid::SafeDownCast(obj))
  {
    DescribeMesh(ug, text, j);
  }
  return j;
}

void Declare(cli::Options& o)
{
  o.Add("array", 0, "NAME", "point array of a volume to describe as its scalars (default: the active scalars)");
  cli::AddLoadOptions(o);
}

int Run(const cli::Options& o)
{
  if (o.Positional().empty())
  {
    throw cli::UsageError("needs at least one FILE");
  }
  const art::LoadOptions load = cli::LoadOptionsFrom(o); // a usage error before any file
  std::vector<cli::Json> all;
  int failures = 0;
  for (const auto& path : o.Positional())
  {
    try
    {
      art::DataKind kind;
      auto obj = art::Load(path, load, &kind);
      std::string text;
      all.push_back(Describe(path, obj, kind, text));
      if (!o.Flag("json"))
      {
        std::fputs(text.c_str(), stdout);
      }
    }
    catch (const art::Error& e)
    {
      std::fprintf(stderr, "adaptivert: %s\n", e.what());
      ++failures;
    }
  }
  if (o.Flag("json"))
  {
    cli::Json out;
    out.Set("files", all);
    std::printf("%s\n", out.Str().c_str());
  }
  return failures ? cli::ExitFailure : cli::ExitOk;
}

cli::Registrar reg({ "info", "describe volumes, surfaces and meshes (sizes, types, ranges, bounds)",
  "adaptivert info [options] FILE...",
  "  adaptivert info data/ct-head-128.mha\n  adaptivert info --json data/am_underworks.ply mesh.vtu\n",
  Declare, Run });
} // namespace
