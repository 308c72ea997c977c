#include "rendering/MeshCache.h"

#ifdef ART_HAVE_Reduction
#include "DataLoader.h"
#include "Error.h"
#include "MmgRemesher.h"
#include "ReducerVTK.h"
#include "SourceStatistics.h"
#include "cli/Subprocess.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <dlfcn.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace fs = std::filesystem;

namespace cli
{
namespace
{
// Field data naming what the entry was made from; a file without it, or with another, is a miss.
constexpr const char* KeyArray = "adaptivert_mesh_cache_key";

// Two independent 64-bit multiply-rotate lanes over the samples' bytes: not cryptographic, only
// so that any edit of a volume changes its key.
struct Hash128
{
  std::uint64_t a = 0x9E3779B97F4A7C15ull, b = 0xC2B2AE3D27D4EB4Full;
  void Add(const void* data, std::size_t n)
  {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    std::uint64_t w;
    for (; n >= 8; n -= 8, p += 8)
    {
      std::memcpy(&w, p, 8);
      Mix(w);
    }
    w = 0;
    std::memcpy(&w, p, n);
    Mix(w ^ (static_cast<std::uint64_t>(n) << 56));
  }
  void Mix(std::uint64_t w)
  {
    a = Rotl((a ^ w) * 0x87C37B91114253D5ull, 31);
    b = Rotl((b + w) * 0x4CF5AD432745937Full, 29) ^ (a >> 17);
  }
  static std::uint64_t Rotl(std::uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }
};

// A file's identity for the key: its path, size and modification time.
std::string FileStamp(const std::string& path)
{
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  const auto time = fs::last_write_time(path, ec);
  std::ostringstream ss;
  ss << path << ":" << (ec ? 0 : size) << ":" << (ec ? 0 : time.time_since_epoch().count());
  return ss.str();
}

// The shared library (or executable) holding `symbol`.
std::string FileOf(const void* symbol)
{
  Dl_info info;
  return dladdr(symbol, &info) && info.dli_fname ? FileStamp(info.dli_fname) : std::string("?");
}

double Field(vtkFieldData* fd, const char* name, double fallback = 0.0)
{
  vtkDataArray* a = fd->GetArray(name);
  return a && a->GetNumberOfTuples() == 1 ? a->GetTuple1(0) : fallback;
}

void AddField(vtkFieldData* fd, const char* name, double v)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(v);
  fd->AddArray(a);
}

// The reduced mesh back from the grid ToUnstructuredGrid made (and Store added to): false when
// anything is missing or out of place.
bool FromGrid(vtkUnstructuredGrid* g, art::ReducedMesh& m)
{
  const vtkIdType nv = g->GetNumberOfPoints(), nt = g->GetNumberOfCells();
  vtkDataArray* values = g->GetPointData()->GetScalars();
  vtkDataArray* rms = g->GetCellData()->GetArray("approximation_error");
  vtkDataArray* max = g->GetCellData()->GetArray("max_error");
  if (!values || values->GetNumberOfComponents() != 1 || !rms || !max)
  {
    return false;
  }
  m.Points.resize(3 * static_cast<std::size_t>(nv));
  m.Values.resize(static_cast<std::size_t>(nv));
  for (vtkIdType i = 0; i < nv; ++i)
  {
    g->GetPoint(i, &m.Points[3 * static_cast<std::size_t>(i)]);
    m.Values[static_cast<std::size_t>(i)] = values->GetTuple1(i);
  }
  m.Tets.resize(4 * static_cast<std::size_t>(nt));
  m.TetRms.resize(static_cast<std::size_t>(nt));
  m.TetMax.resize(static_cast<std::size_t>(nt));
  vtkNew<vtkIdList> ids;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    g->GetCellPoints(t, ids);
    if (g->GetCellType(t) != VTK_TETRA || ids->GetNumberOfIds() != 4)
    {
      return false;
    }
    for (int k = 0; k < 4; ++k)
    {
      m.Tets[4 * static_cast<std::size_t>(t) + k] = static_cast<int>(ids->GetId(k));
    }
    m.TetRms[static_cast<std::size_t>(t)] = rms->GetTuple1(t);
    m.TetMax[static_cast<std::size_t>(t)] = max->GetTuple1(t);
  }
  vtkFieldData* fd = g->GetFieldData();
  m.ScalarName = values->GetName() ? values->GetName() : "";
  m.Rms = Field(fd, "rms_error");
  m.Max = Field(fd, "max_error");
  m.Weighted = Field(fd, "weighted") != 0.0;
  m.WeightedRms = Field(fd, "weighted_rms_error");
  m.WeightedMax = Field(fd, "weighted_max_error");
  m.Range[0] = Field(fd, "scalar_range_min");
  m.Range[1] = Field(fd, "scalar_range_max");
  m.SourceSpacing = Field(fd, "source_spacing", 1.0);
  art::ReadSourceStatistics(fd, m.Source);
  m.BuildSeconds = Field(fd, "build_seconds");
  m.TargetTets = static_cast<long long>(Field(fd, "target_tets"));
  m.TargetError = Field(fd, "target_error", -1.0);
  m.TargetReached = Field(fd, "target_reached", 1.0) != 0.0;
  m.RefinementLevels = static_cast<int>(Field(fd, "refinement_levels"));
  m.SolverIterations = static_cast<int>(Field(fd, "solver_iterations"));
  m.Nested = Field(fd, "levels_nested", 1.0) != 0.0;
  m.Relocated = Field(fd, "vertices_relocated", 0.0) != 0.0;
  if (auto* r = vtkStringArray::SafeDownCast(fd->GetAbstractArray("refinement")))
  {
    m.Refinement = r->GetNumberOfValues() ? r->GetValue(0) : m.Refinement;
  }
  return true;
}
} // namespace

MeshCache::MeshCache(const std::string& dir, const art::VoxelVolume& v, const art::ReducerOptions& o)
{
  std::ostringstream k;
  k.precision(17);
  k << "volume " << v.Dims[0] << "x" << v.Dims[1] << "x" << v.Dims[2] << " " << v.Name << " "
    << (v.DoubleValues ? "double" : "float");
  for (const double* a : { v.Origin, v.Spacing })
  {
    k << " " << a[0] << "," << a[1] << "," << a[2];
  }
  for (double d : v.Direction)
  {
    k << " " << d;
  }
  Hash128 h;
  v.WithSamples([&](const auto* p) { h.Add(p, static_cast<std::size_t>(v.NumberOfVoxels()) * sizeof(*p)); });
  k << " samples " << std::hex << std::setfill('0') << std::setw(16) << h.a << std::setw(16) << h.b << std::dec;
  // Every option, so that a field added to ReducerOptions cannot go unkeyed unnoticed: keep this
  // list whole.
  k << "\noptions " << o.TargetTets << " " << o.TargetError << " " << int(o.ErrorMetric) << " " << o.ErrorRelative
    << " " << o.RefineFraction << " " << o.SolverTolerance << " " << o.Regularization << " " << o.MinEdgeVoxels
    << " " << int(o.Refine) << " " << o.CoarseTets << " " << o.ClampToVoxels << " " << o.CapOpacity << " "
    << o.ImportanceFloor << " " << o.ImportanceRadius << " " << o.ReweighSteps << " " << o.RelocateVertices << " "
    << o.RelocateSweeps << " " << o.RelocateQualityFloor << " " << o.RelocateVoxelsPerTet << " metric " << o.Metric.Sigma << " " << o.Metric.TensorSigma
    << " " << o.Metric.Exponent << " " << o.Metric.Hmin << " " << o.Metric.Hmax << " " << o.Metric.Floor << " "
    << o.MetricWeightExponent << " " << o.RemeshMovesVertices << " " << o.AdaptationRetries << " " << o.BudgetTolerance
    << " levels";
  for (long long l : o.Levels)
  {
    k << " " << l;
  }
  k << " iso";
  for (double v : o.IsoValues)
  {
    k << " " << v;
  }
  k << " opacity";
  for (const auto& n : o.ScalarOpacity)
  {
    k << " " << n.first << ":" << n.second;
  }
  k << "\ntool " << FileStamp(SelfExecutable()) << " "
    << FileOf(reinterpret_cast<const void*>(&art::TetReducer::CoarseGrid));
  if (o.Refine == art::ReducerOptions::Refinement::Anisotropic)
  {
    k << " " << FileStamp(art::MmgRemesher::LibraryPath());
  }
  Key = k.str();
  Hash128 kh;
  kh.Add(Key.data(), Key.size());
  std::ostringstream name;
  name << std::hex << std::setfill('0') << std::setw(16) << kh.a << std::setw(16) << kh.b << ".vtu";
  Path = (fs::path(dir) / name.str()).string();
}

bool MeshCache::Load(art::ReducedMesh& m) const
{
  std::error_code ec;
  if (!fs::is_regular_file(Path, ec))
  {
    return false;
  }
  try
  {
    vtkSmartPointer<vtkUnstructuredGrid> g = art::LoadMesh(Path);
    auto* key = vtkStringArray::SafeDownCast(g->GetFieldData()->GetAbstractArray(KeyArray));
    art::ReducedMesh out;
    if (!key || key->GetNumberOfValues() != 1 || key->GetValue(0) != Key || !FromGrid(g, out))
    {
      return false;
    }
    m = std::move(out);
    return true;
  }
  catch (const art::Error&) // damaged or not ours: a miss, made again
  {
    return false;
  }
}

void MeshCache::Store(const art::ReducedMesh& m) const
{
  vtkSmartPointer<vtkUnstructuredGrid> g = art::ToUnstructuredGrid(m, true); // values in double, as fitted
  vtkFieldData* fd = g->GetFieldData();
  AddField(fd, "refinement_levels", m.RefinementLevels);
  AddField(fd, "solver_iterations", m.SolverIterations);
  vtkNew<vtkStringArray> key;
  key->SetName(KeyArray);
  key->InsertNextValue(Key);
  fd->AddArray(key);
  std::error_code ec;
  fs::create_directories(fs::path(Path).parent_path(), ec);
  if (ec)
  {
    throw art::Error("cannot create the mesh cache folder: " + ec.message(), fs::path(Path).parent_path().string());
  }
  art::SaveMesh(g, Path);
}
} // namespace cli
#endif
