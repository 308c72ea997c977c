#include "MmgRemesher.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <mutex>

#ifdef ART_HAVE_MMG
#include "mmg/mmg3d/libmmg3d.h"

#include <dlfcn.h>
#endif

namespace art
{
#ifdef ART_HAVE_MMG
namespace
{
constexpr const char* SoName = "libmmg3d.so.5";

// libmmg3d's entry points, resolved from the loaded library.
struct MmgApi
{
  decltype(&MMG3D_Init_mesh) InitMesh = nullptr;
  decltype(&MMG3D_Free_all) FreeAll = nullptr;
  decltype(&MMG3D_Set_meshSize) SetMeshSize = nullptr;
  decltype(&MMG3D_Set_vertices) SetVertices = nullptr;
  decltype(&MMG3D_Set_tetrahedra) SetTetrahedra = nullptr;
  decltype(&MMG3D_Set_solSize) SetSolSize = nullptr;
  decltype(&MMG3D_Set_tensorSols) SetTensorSols = nullptr;
  decltype(&MMG3D_Set_iparameter) SetIParameter = nullptr;
  decltype(&MMG3D_Set_dparameter) SetDParameter = nullptr;
  decltype(&MMG3D_mmg3dlib) Run = nullptr;
  decltype(&MMG3D_Get_meshSize) GetMeshSize = nullptr;
  decltype(&MMG3D_Get_vertices) GetVertices = nullptr;
  decltype(&MMG3D_Get_tetrahedra) GetTetrahedra = nullptr;
  std::string Path, Problem; // Problem empty: loaded
};

// The directory of the library holding this function (ours), where an install puts MMG too.
std::string OwnDirectory()
{
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&OwnDirectory), &info) && info.dli_fname)
  {
    const std::string f = info.dli_fname;
    const size_t slash = f.find_last_of('/');
    return slash == std::string::npos ? std::string(".") : f.substr(0, slash);
  }
  return {};
}

std::string FindLibrary()
{
  if (const char* env = std::getenv("ART_MMG_LIBRARY"))
  {
    if (*env)
    {
      return env;
    }
  }
  const std::string dir = OwnDirectory();
  if (!dir.empty())
  {
    const std::string beside = dir + "/" + SoName;
    if (FILE* f = std::fopen(beside.c_str(), "rb"))
    {
      std::fclose(f);
      return beside;
    }
  }
  return SoName; // the system's search (LD_LIBRARY_PATH, ld.so.cache)
}

template <class F>
bool Resolve(void* handle, const char* name, F& f, MmgApi& api)
{
  f = reinterpret_cast<F>(dlsym(handle, name));
  if (!f && api.Problem.empty())
  {
    api.Problem = api.Path + " is not MMG 5's libmmg3d (it has no " + name + ")";
  }
  return f != nullptr;
}

const MmgApi& Api()
{
  static const MmgApi api = [] {
    MmgApi a;
    a.Path = FindLibrary();
    void* h = dlopen(a.Path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!h)
    {
      const char* e = dlerror();
      a.Problem = "cannot load " + a.Path + ": " + (e ? e : "unknown error");
      return a;
    }
    Resolve(h, "MMG3D_Init_mesh", a.InitMesh, a);
    Resolve(h, "MMG3D_Free_all", a.FreeAll, a);
    Resolve(h, "MMG3D_Set_meshSize", a.SetMeshSize, a);
    Resolve(h, "MMG3D_Set_vertices", a.SetVertices, a);
    Resolve(h, "MMG3D_Set_tetrahedra", a.SetTetrahedra, a);
    Resolve(h, "MMG3D_Set_solSize", a.SetSolSize, a);
    Resolve(h, "MMG3D_Set_tensorSols", a.SetTensorSols, a);
    Resolve(h, "MMG3D_Set_iparameter", a.SetIParameter, a);
    Resolve(h, "MMG3D_Set_dparameter", a.SetDParameter, a);
    Resolve(h, "MMG3D_mmg3dlib", a.Run, a);
    Resolve(h, "MMG3D_Get_meshSize", a.GetMeshSize, a);
    Resolve(h, "MMG3D_Get_vertices", a.GetVertices, a);
    Resolve(h, "MMG3D_Get_tetrahedra", a.GetTetrahedra, a);
    return a; // the handle stays open for the process's life
  }();
  return api;
}

const MmgApi& RequireApi()
{
  const MmgApi& a = Api();
  if (!a.Problem.empty())
  {
    throw Error("anisotropic refinement needs MMG (libmmg3d 5.8): " + a.Problem +
      "; cmake/setup.sh installs it beside AdaptiveRT's libraries, or set ART_MMG_LIBRARY to its path");
  }
  return a;
}

// MMG installs its own handlers for these (they print and exit): the caller's come back after.
class SignalGuard
{
public:
  SignalGuard()
  {
    for (int i = 0; i < N; ++i)
    {
      sigaction(Signals[i], nullptr, &Saved[i]);
    }
  }
  ~SignalGuard()
  {
    for (int i = 0; i < N; ++i)
    {
      sigaction(Signals[i], &Saved[i], nullptr);
    }
  }
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;

private:
  static constexpr int N = 6;
  static constexpr int Signals[N] = { SIGABRT, SIGFPE, SIGILL, SIGSEGV, SIGTERM, SIGINT };
  struct sigaction Saved[N];
};

// The MMG structures of one call, freed on every way out.
class MmgSession
{
public:
  explicit MmgSession(const MmgApi& api)
    : A(api)
  {
    if (!A.InitMesh(MMG5_ARG_start, MMG5_ARG_ppMesh, &Mesh, MMG5_ARG_ppMet, &Met, MMG5_ARG_end))
    {
      throw Error("MMG could not set up a mesh");
    }
  }
  ~MmgSession() { A.FreeAll(MMG5_ARG_start, MMG5_ARG_ppMesh, &Mesh, MMG5_ARG_ppMet, &Met, MMG5_ARG_end); }
  MmgSession(const MmgSession&) = delete;
  MmgSession& operator=(const MmgSession&) = delete;

  const MmgApi& A;
  MMG5_pMesh Mesh = nullptr;
  MMG5_pSol Met = nullptr;
};

void Check(int ok, const char* what)
{
  if (!ok)
  {
    throw Error(std::string("MMG refused ") + what);
  }
}

std::mutex& MmgMutex()
{
  static std::mutex m;
  return m;
}
} // namespace

bool MmgRemesher::Available(std::string* why)
{
  const MmgApi& a = Api();
  if (why)
  {
    *why = a.Problem;
  }
  return a.Problem.empty();
}

std::string MmgRemesher::LibraryPath()
{
  return Api().Path;
}

namespace
{
// One MMG3D run on `in`; MMG sizes its arrays for `memoryMB` (0: its default, half the machine).
// Returns MMG's status; the mesh is read back on success.
int RunMmg(const MmgApi& A, const MetricMesh& in, const RemeshOptions& options, int memoryMB, std::vector<double>& points,
  std::vector<int>& tets)
{
  const MMG5_int np = static_cast<MMG5_int>(in.Points.size() / 3), ne = static_cast<MMG5_int>(in.Tets.size() / 4);
  MmgSession s(A);
  // Verbosity and memory first: the arrays are sized when the mesh size is set.
  Check(A.SetIParameter(s.Mesh, s.Met, MMG3D_IPARAM_verbose, options.Verbose), "verbose");
  if (memoryMB > 0)
  {
    Check(A.SetIParameter(s.Mesh, s.Met, MMG3D_IPARAM_mem, memoryMB), "its memory size");
  }
  Check(A.SetMeshSize(s.Mesh, np, ne, 0, 0, 0, 0), "the mesh size");
  std::vector<double> xyz(in.Points);
  Check(A.SetVertices(s.Mesh, xyz.data(), nullptr), "the vertices");
  std::vector<MMG5_int> tv(in.Tets.size());
  for (size_t i = 0; i < tv.size(); ++i)
  {
    tv[i] = static_cast<MMG5_int>(in.Tets[i]) + 1; // MMG counts from 1
  }
  Check(A.SetTetrahedra(s.Mesh, tv.data(), nullptr), "the tetrahedra");
  Check(A.SetSolSize(s.Mesh, s.Met, MMG5_Vertex, np, MMG5_Tensor), "the metric size");
  std::vector<double> m(in.Metric); // m11 m12 m13 m22 m23 m33, the API's order
  Check(A.SetTensorSols(s.Met, m.data()), "the metric");
  Check(A.SetIParameter(s.Mesh, s.Met, MMG3D_IPARAM_angle, 1), "angle detection");
  Check(A.SetIParameter(s.Mesh, s.Met, MMG3D_IPARAM_nomove, options.NoMove ? 1 : 0), "nomove");
  Check(A.SetDParameter(s.Mesh, s.Met, MMG3D_DPARAM_angleDetection, 45.0), "the ridge angle");
  Check(A.SetDParameter(s.Mesh, s.Met, MMG3D_DPARAM_hmin, options.Hmin), "hmin");
  Check(A.SetDParameter(s.Mesh, s.Met, MMG3D_DPARAM_hmax, options.Hmax), "hmax");
  Check(A.SetDParameter(s.Mesh, s.Met, MMG3D_DPARAM_hausd, options.Hausd), "hausd");
  Check(A.SetDParameter(s.Mesh, s.Met, MMG3D_DPARAM_hgrad, options.Hgrad), "hgrad");
  int status;
  {
    SignalGuard guard;
    status = A.Run(s.Mesh, s.Met);
  }
  if (status != MMG5_SUCCESS)
  {
    return status;
  }
  MMG5_int onp = 0, one = 0, nprism = 0, nt = 0, nquad = 0, na = 0;
  Check(A.GetMeshSize(s.Mesh, &onp, &one, &nprism, &nt, &nquad, &na), "to give its mesh size");
  points.resize(3 * static_cast<size_t>(onp));
  Check(A.GetVertices(s.Mesh, points.data(), nullptr, nullptr, nullptr), "to give its vertices");
  std::vector<MMG5_int> ot(4 * static_cast<size_t>(one));
  Check(A.GetTetrahedra(s.Mesh, ot.data(), nullptr, nullptr), "to give its tetrahedra");
  tets.resize(ot.size());
  for (size_t i = 0; i < ot.size(); ++i)
  {
    tets[i] = static_cast<int>(ot[i]) - 1;
  }
  return status;
}

// Boundary points back on the box's planes: MMG moves them along its reconstruction of the
// surface, which for a plane is the plane up to round-off.
void SnapToBox(std::vector<double>& points, const double boxLo[3], const double boxHi[3])
{
  for (size_t v = 0; v < points.size() / 3; ++v)
  {
    for (int d = 0; d < 3; ++d)
    {
      double& c = points[3 * v + d];
      const double tol = 1e-7 * std::max(1.0, boxHi[d] - boxLo[d]);
      c = std::fabs(c - boxLo[d]) <= tol ? boxLo[d] : (std::fabs(c - boxHi[d]) <= tol ? boxHi[d] : c);
      c = std::min(boxHi[d], std::max(boxLo[d], c));
    }
  }
}
} // namespace

void MmgRemesher::Remesh(const MetricMesh& in, const double boxLo[3], const double boxHi[3],
  const RemeshOptions& options, std::vector<double>& points, std::vector<int>& tets)
{
  const MmgApi& A = RequireApi();
  const size_t np = in.Points.size() / 3;
  if (np < 4 || in.Tets.size() < 4 || in.Metric.size() != 6 * np || in.Points.size() != 3 * np)
  {
    throw Error("internal: a remeshing input needs points, tets and a metric per point");
  }
  std::lock_guard<std::mutex> lock(MmgMutex());
  // MMG links every free slot of its arrays on each pass, so arrays sized for the machine (its
  // default) cost seconds on a small mesh: they are sized for the mesh, and for MMG's default
  // only when that was too little.
  const double vertices = std::max<double>(np, options.ExpectedVertices);
  const int sized = static_cast<int>(std::min(1e6, 64 + 0.004 * vertices));
  int status = RunMmg(A, in, options, sized, points, tets);
  if (status != MMG5_SUCCESS)
  {
    status = RunMmg(A, in, options, 0, points, tets);
  }
  if (status != MMG5_SUCCESS)
  {
    throw Error(std::string("MMG could not remesh to the metric (") +
      (status == MMG5_LOWFAILURE ? "it stopped short" : "it failed") + ")");
  }
  SnapToBox(points, boxLo, boxHi);
}
#else
bool MmgRemesher::Available(std::string* why)
{
  if (why)
  {
    *why = "this build of AdaptiveRT has no MMG (configure it with MMG found, e.g. by cmake/setup.sh)";
  }
  return false;
}

std::string MmgRemesher::LibraryPath()
{
  return {};
}

void MmgRemesher::Remesh(const MetricMesh&, const double*, const double*, const RemeshOptions&, std::vector<double>&,
  std::vector<int>&)
{
  std::string why;
  Available(&why);
  throw Error("anisotropic refinement needs MMG: " + why);
}
#endif
} // namespace art
