#include "ReducerVTK.h"

#include "AvailableMemory.h"
#include "Error.h"
#include "SourceStatistics.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace art
{
bool ReducedAsDouble(int type)
{
  return type == VTK_DOUBLE || type == VTK_LONG_LONG || type == VTK_UNSIGNED_LONG_LONG || type == VTK_LONG ||
    type == VTK_UNSIGNED_LONG || type == VTK_ID_TYPE || type == VTK_INT || type == VTK_UNSIGNED_INT;
}

VoxelVolume VolumeFromImage(vtkImageData* image, const std::string& file)
{
  if (!image)
  {
    throw Error("no input image", file);
  }
  VoxelVolume v;
  image->GetDimensions(v.Dims);
  image->GetOrigin(v.Origin);
  image->GetSpacing(v.Spacing);
  // Extents need not start at 0: the origin moves to the first voxel.
  int ext[6];
  image->GetExtent(ext);
  if (vtkMatrix3x3* m = image->GetDirectionMatrix())
  {
    for (int i = 0; i < 9; ++i)
    {
      v.Direction[i] = m->GetData()[i];
    }
  }
  {
    const double first[3] = { double(ext[0]) * v.Spacing[0], double(ext[2]) * v.Spacing[1], double(ext[4]) * v.Spacing[2] };
    double o[3];
    for (int r = 0; r < 3; ++r)
    {
      o[r] = v.Origin[r] + v.Direction[3 * r] * first[0] + v.Direction[3 * r + 1] * first[1] +
        v.Direction[3 * r + 2] * first[2];
    }
    std::copy(o, o + 3, v.Origin);
  }
  if (image->GetNumberOfPoints() == 0 || v.Dims[0] <= 0 || v.Dims[1] <= 0 || v.Dims[2] <= 0)
  {
    throw Error("the image is empty", file);
  }
  for (int a = 0; a < 3; ++a)
  {
    // A zero spacing gave tets of zero volume without a word; a negative one (kept by VTK's
    // readers) is a flipped axis: its sign moves into the direction, every voxel staying put.
    if (v.Dims[a] > 1 && (!std::isfinite(v.Spacing[a]) || v.Spacing[a] == 0.0))
    {
      throw Error("the spacing along axis " + std::to_string(a) + " is " + std::to_string(v.Spacing[a]) +
          "; voxels need a positive, finite spacing",
        file);
    }
    if (v.Spacing[a] < 0)
    {
      v.Spacing[a] = -v.Spacing[a];
      for (int r = 0; r < 3; ++r)
      {
        v.Direction[3 * r + a] = -v.Direction[3 * r + a];
      }
    }
  }
  vtkDataArray* s = image->GetPointData()->GetScalars();
  if (!s)
  {
    throw Error("the image has no point scalars", file);
  }
  if (s->GetNumberOfComponents() != 1)
  {
    throw Error("the scalars have " + std::to_string(s->GetNumberOfComponents()) +
        " components; the reducer needs one (extract a component first)",
      file);
  }
  v.Name = s->GetName() ? s->GetName() : "scalars";
  const long long n = v.NumberOfVoxels();
  if (s->GetNumberOfTuples() != n)
  {
    throw Error("the scalar array does not match the image dimensions", file);
  }
  v.DoubleValues = ReducedAsDouble(s->GetDataType());
  // The reducer's own copy of the samples; TetReducer::Run checks the rest of what it needs.
  const double copyBytes = (v.DoubleValues ? 8.0 : 4.0) * double(n), available = AvailableMemoryBytes();
  if (ExceedsAvailableMemory(copyBytes, available))
  {
    char msg[400];
    std::snprintf(msg, sizeof msg,
      "reducing this volume of %d x %d x %d = %lld voxels needs about %.3g GB for its samples alone, more than "
      "the %.3g GB of memory available; crop or resample it first (e.g. vtkImageResample, ParaView's Resample "
      "To Image or Extract Subset)",
      v.Dims[0], v.Dims[1], v.Dims[2], n, copyBytes / 1e9, available / 1e9);
    throw Error(msg, file);
  }
  if (v.DoubleValues)
  {
    v.Double.resize(static_cast<size_t>(n));
    for (long long i = 0; i < n; ++i)
    {
      v.Double[i] = s->GetComponent(i, 0);
    }
  }
  else
  {
    v.Float.resize(static_cast<size_t>(n));
    if (auto* f = vtkFloatArray::SafeDownCast(s))
    {
      std::copy(f->GetPointer(0), f->GetPointer(0) + n, v.Float.begin());
    }
    else
    {
      for (long long i = 0; i < n; ++i)
      {
        v.Float[i] = static_cast<float>(s->GetComponent(i, 0));
      }
    }
  }
  v.File = file;
  v.Validate(file);
  return v;
}

vtkSmartPointer<vtkUnstructuredGrid> ToUnstructuredGrid(const ReducedMesh& m, bool doubleValues, const QualityReport* quality)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  const vtkIdType nv = m.NumberOfVertices(), nt = m.NumberOfTets();
  auto pts = vtkSmartPointer<vtkPoints>::New();
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(nv);
  for (vtkIdType i = 0; i < nv; ++i)
  {
    pts->SetPoint(i, &m.Points[3 * i]);
  }
  grid->SetPoints(pts);

  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto conn = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(nt + 1);
  conn->SetNumberOfValues(4 * nt);
  for (vtkIdType t = 0; t <= nt; ++t)
  {
    offsets->SetValue(t, 4 * t);
  }
  for (vtkIdType i = 0; i < 4 * nt; ++i)
  {
    conn->SetValue(i, m.Tets[i]);
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, conn);
  grid->SetCells(VTK_TETRA, cells);

  vtkSmartPointer<vtkDataArray> values;
  if (m.Values.empty()) // a mesh without a field (a label map's, a surface's): no point scalars
  {
  }
  else if (doubleValues)
  {
    values = vtkSmartPointer<vtkDoubleArray>::New();
  }
  else
  {
    values = vtkSmartPointer<vtkFloatArray>::New();
  }
  if (values)
  {
    values->SetName(m.ScalarName.c_str());
    values->SetNumberOfTuples(nv);
    for (vtkIdType i = 0; i < nv; ++i)
    {
      values->SetTuple1(i, m.Values[i]);
    }
    grid->GetPointData()->SetScalars(values);
  }

  auto cellArray = [&](const char* name, const std::vector<double>& a) {
    auto arr = vtkSmartPointer<vtkFloatArray>::New();
    arr->SetName(name);
    arr->SetNumberOfTuples(nt);
    for (vtkIdType t = 0; t < nt; ++t)
    {
      arr->SetValue(t, static_cast<float>(a[t]));
    }
    grid->GetCellData()->AddArray(arr);
  };
  if (!m.TetRms.empty())
  {
    cellArray("approximation_error", m.TetRms);
    cellArray("max_error", m.TetMax);
    grid->GetCellData()->SetActiveScalars("approximation_error");
  }

  vtkFieldData* fd = grid->GetFieldData();
  auto field = [&](const char* name, double v) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name);
    a->SetNumberOfTuples(1);
    a->SetValue(0, v);
    fd->AddArray(a);
  };
  field("rms_error", m.Rms);
  field("max_error", m.Max);
  field("weighted", m.Weighted ? 1.0 : 0.0);
  field("weighted_rms_error", m.WeightedRms);
  field("weighted_max_error", m.WeightedMax);
  field("tets", static_cast<double>(nt));
  field("vertices", static_cast<double>(nv));
  field("build_seconds", m.BuildSeconds);
  field("target_tets", static_cast<double>(m.TargetTets));
  field("target_error", m.TargetError);
  field("target_reached", m.TargetReached ? 1.0 : 0.0);
  const QualityReport q = quality ? *quality : MeasureQuality(m.Points.data(), nv, m.Tets.data(), nt);
  field("min_dihedral_degrees", q.MinDihedralDegrees);
  field("min_radius_ratio", q.MinRadiusRatio);
  field("mean_radius_ratio", q.MeanRadiusRatio);
  field("scalar_range_min", m.Range[0]);
  field("scalar_range_max", m.Range[1]);
  field("source_spacing", m.SourceSpacing);
  if (m.Source.samples > 0)
  {
    WriteSourceStatistics(fd, m.Source);
  }
  field("levels_nested", m.Nested ? 1.0 : 0.0);
  field("vertices_relocated", m.Relocated ? 1.0 : 0.0);
  auto refinement = vtkSmartPointer<vtkStringArray>::New();
  refinement->SetName("refinement");
  refinement->InsertNextValue(m.Refinement);
  fd->AddArray(refinement);
  return grid;
}

QualityReport MeasureQuality(vtkUnstructuredGrid* grid)
{
  const vtkIdType nv = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  std::vector<double> p(3 * static_cast<size_t>(nv));
  for (vtkIdType i = 0; i < nv; ++i)
  {
    grid->GetPoint(i, &p[3 * i]);
  }
  std::vector<int> t;
  t.reserve(4 * static_cast<size_t>(nc));
  long long other = 0;
  for (vtkIdType c = 0; c < nc; ++c)
  {
    if (grid->GetCellType(c) != VTK_TETRA)
    {
      ++other;
      continue;
    }
    vtkIdType npts;
    const vtkIdType* ids;
    grid->GetCellPoints(c, npts, ids);
    for (int a = 0; a < 4; ++a)
    {
      t.push_back(static_cast<int>(ids[a]));
    }
  }
  QualityReport q = MeasureQuality(p.data(), nv, t.data(), static_cast<long long>(t.size() / 4));
  q.Inverted += other;
  q.Tets += other;
  return q;
}
} // namespace art
