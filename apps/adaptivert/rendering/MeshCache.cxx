#include "rendering/MeshCache.h"

#ifdef ART_HAVE_Reduction
#include "AtomicFile.h"
#include "Error.h"
#include "cli/Subprocess.h"

#include <dlfcn.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>

namespace fs = std::filesystem;

namespace cli
{
namespace
{
constexpr char Magic[8] = { 'A', 'R', 'T', 'M', 'E', 'S', 'H', '1' };
constexpr char End[4] = { 'E', 'N', 'D', '!' };

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

template <class T>
void Put(std::string& out, const T& v)
{
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

template <class T>
void PutVector(std::string& out, const std::vector<T>& v)
{
  Put(out, static_cast<std::uint64_t>(v.size()));
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// Reads what Put wrote; any read past the end marks the whole file bad.
struct Reader
{
  const std::string& s;
  std::size_t at = 0;
  bool ok = true;
  template <class T>
  void Get(T& v)
  {
    if (!ok || s.size() - at < sizeof(T))
    {
      ok = false;
      return;
    }
    std::memcpy(&v, s.data() + at, sizeof(T));
    at += sizeof(T);
  }
  template <class T>
  void GetVector(std::vector<T>& v)
  {
    std::uint64_t n = 0;
    Get(n);
    if (!ok || n > (s.size() - at) / sizeof(T))
    {
      ok = false;
      return;
    }
    v.resize(n);
    std::memcpy(v.data(), s.data() + at, n * sizeof(T));
    at += n * sizeof(T);
  }
};
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
    << o.RelocateSweeps << " " << o.RelocateQualityFloor << " levels";
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
  Key = k.str();
  Hash128 kh;
  kh.Add(Key.data(), Key.size());
  std::ostringstream name;
  name << std::hex << std::setfill('0') << std::setw(16) << kh.a << std::setw(16) << kh.b << ".artmesh";
  Path = (fs::path(dir) / name.str()).string();
}

bool MeshCache::Load(art::ReducedMesh& m) const
{
  std::ifstream in(Path, std::ios::binary);
  if (!in)
  {
    return false;
  }
  const std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Reader r{ s };
  char magic[8] = {};
  r.Get(magic);
  std::vector<char> key;
  r.GetVector(key);
  if (!r.ok || std::memcmp(magic, Magic, 8) != 0 || std::string(key.begin(), key.end()) != Key)
  {
    return false;
  }
  art::ReducedMesh out;
  std::vector<char> name;
  r.GetVector(out.Points), r.GetVector(out.Tets), r.GetVector(out.Values), r.GetVector(out.TetRms),
    r.GetVector(out.TetMax), r.GetVector(name);
  r.Get(out.Rms), r.Get(out.Max), r.Get(out.WeightedRms), r.Get(out.WeightedMax), r.Get(out.Range),
    r.Get(out.SourceSpacing), r.Get(out.BuildSeconds), r.Get(out.TargetTets), r.Get(out.TargetError),
    r.Get(out.Weighted), r.Get(out.TargetReached), r.Get(out.RefinementLevels), r.Get(out.SolverIterations);
  char end[4] = {};
  r.Get(end);
  const std::size_t nv = out.Points.size() / 3;
  bool ok = r.ok && r.at == s.size() && std::memcmp(end, End, 4) == 0 && out.Points.size() == 3 * nv &&
    out.Values.size() == nv && out.Tets.size() % 4 == 0;
  for (std::size_t i = 0; ok && i < out.Tets.size(); ++i)
  {
    ok = out.Tets[i] >= 0 && static_cast<std::size_t>(out.Tets[i]) < nv;
  }
  if (!ok)
  {
    return false;
  }
  out.ScalarName.assign(name.begin(), name.end());
  m = std::move(out);
  return true;
}

void MeshCache::Store(const art::ReducedMesh& m) const
{
  std::string s(Magic, 8);
  PutVector(s, std::vector<char>(Key.begin(), Key.end()));
  PutVector(s, m.Points), PutVector(s, m.Tets), PutVector(s, m.Values), PutVector(s, m.TetRms),
    PutVector(s, m.TetMax), PutVector(s, std::vector<char>(m.ScalarName.begin(), m.ScalarName.end()));
  Put(s, m.Rms), Put(s, m.Max), Put(s, m.WeightedRms), Put(s, m.WeightedMax), Put(s, m.Range),
    Put(s, m.SourceSpacing), Put(s, m.BuildSeconds), Put(s, m.TargetTets), Put(s, m.TargetError),
    Put(s, m.Weighted), Put(s, m.TargetReached), Put(s, m.RefinementLevels), Put(s, m.SolverIterations);
  s.append(End, 4);
  std::error_code ec;
  fs::create_directories(fs::path(Path).parent_path(), ec);
  if (ec)
  {
    throw art::Error("cannot create the mesh cache folder: " + ec.message(), fs::path(Path).parent_path().string());
  }
  art::WriteFileAtomic(Path, s);
}
} // namespace cli
#endif
