#include "TetGenMesher.h"

#include "Error.h"

#include <tetgen.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>

namespace art
{
namespace
{
std::string Switches(const char* mode, const TetGenSettings& s, bool perTet)
{
  char q[96];
  std::snprintf(q, sizeof q, "%sq%g/%gQ", mode, s.RadiusEdge, s.MinDihedral);
  std::string sw = q;
  if (perTet)
  {
    sw += "a";
  }
  if (s.MaxVolume > 0)
  {
    char a[64];
    std::snprintf(a, sizeof a, "a%.17g", s.MaxVolume);
    sw += a;
  }
  return sw;
}

std::string Why(int code)
{
  switch (code)
  {
    case 1:
      return "TetGen ran out of memory";
    case 3:
      return "TetGen found the surface intersecting itself";
    case 4:
      return "TetGen found features too small for its precision (points or edges nearly touching)";
    case 5:
      return "TetGen found two surface edges or facets nearly overlapping";
    default:
      return "TetGen failed (its code " + std::to_string(code) + ")";
  }
}

double Six(const double* p, const int* t)
{
  const double* a = p + 3 * t[0];
  double e[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      e[r][c] = p[3 * t[r + 1] + c] - a[c];
    }
  }
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
    e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

TetGenMesh Collect(const tetgenio& out)
{
  TetGenMesh m;
  m.Points.assign(out.pointlist, out.pointlist + 3 * out.numberofpoints);
  m.Tets.resize(4 * static_cast<size_t>(out.numberoftetrahedra));
  for (int t = 0; t < out.numberoftetrahedra; ++t)
  {
    int* c = &m.Tets[4 * static_cast<size_t>(t)];
    for (int k = 0; k < 4; ++k)
    {
      c[k] = out.tetrahedronlist[out.numberofcorners * t + k] - out.firstnumber;
    }
    if (Six(m.Points.data(), c) < 0)
    {
      std::swap(c[1], c[2]);
    }
  }
  return m;
}

void Run(const std::string& sw, tetgenio& in, tetgenio& out)
{
  std::vector<char> s(sw.begin(), sw.end());
  s.push_back('\0');
  try
  {
    tetrahedralize(s.data(), &in, &out);
  }
  catch (int code)
  {
    throw Error(Why(code));
  }
}

// The faces of exactly one tet: the mesh's boundary, kept as constrained faces by -r.
std::vector<std::array<int, 3>> BoundaryFaces(const TetGenMesh& m)
{
  std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> faces;
  static const int F[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };
  for (size_t t = 0; t < m.Tets.size() / 4; ++t)
  {
    for (const auto& f : F)
    {
      std::array<int, 3> tri = { m.Tets[4 * t + f[0]], m.Tets[4 * t + f[1]], m.Tets[4 * t + f[2]] };
      std::array<int, 3> key = tri;
      std::sort(key.begin(), key.end());
      auto& e = faces[key];
      e.first += 1;
      e.second = tri;
    }
  }
  std::vector<std::array<int, 3>> out;
  for (const auto& [k, e] : faces)
  {
    if (e.first == 1)
    {
      out.push_back(e.second);
    }
  }
  return out;
}
} // namespace

TetGenMesh MeshSurface(const TriangleSurface& surface, const TetGenSettings& settings)
{
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(surface.Points.size() / 3);
  in.pointlist = new REAL[surface.Points.size()];
  std::copy(surface.Points.begin(), surface.Points.end(), in.pointlist);
  in.numberoffacets = static_cast<int>(surface.Triangles.size());
  in.facetlist = new tetgenio::facet[in.numberoffacets];
  for (int f = 0; f < in.numberoffacets; ++f)
  {
    tetgenio::facet& fc = in.facetlist[f];
    tetgenio::init(&fc);
    fc.numberofpolygons = 1;
    fc.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&fc.polygonlist[0]);
    fc.polygonlist[0].numberofvertices = 3;
    fc.polygonlist[0].vertexlist = new int[3];
    std::copy(surface.Triangles[f].begin(), surface.Triangles[f].end(), fc.polygonlist[0].vertexlist);
  }
  Run(Switches("p", settings, false), in, out);
  return Collect(out);
}

TetGenMesh RefineMesh(const TetGenMesh& mesh, const std::vector<double>& maxVolume, const TetGenSettings& settings)
{
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(mesh.Points.size() / 3);
  in.pointlist = new REAL[mesh.Points.size()];
  std::copy(mesh.Points.begin(), mesh.Points.end(), in.pointlist);
  in.numberoftetrahedra = static_cast<int>(mesh.Tets.size() / 4);
  in.numberofcorners = 4;
  in.tetrahedronlist = new int[mesh.Tets.size()];
  std::copy(mesh.Tets.begin(), mesh.Tets.end(), in.tetrahedronlist);
  in.tetrahedronvolumelist = new REAL[in.numberoftetrahedra];
  for (int t = 0; t < in.numberoftetrahedra; ++t)
  {
    in.tetrahedronvolumelist[t] = maxVolume[t] > 0 ? maxVolume[t] : -1.0;
  }
  const auto faces = BoundaryFaces(mesh);
  in.numberoftrifaces = static_cast<int>(faces.size());
  in.trifacelist = new int[3 * faces.size()];
  in.trifacemarkerlist = new int[faces.size()];
  for (size_t f = 0; f < faces.size(); ++f)
  {
    std::copy(faces[f].begin(), faces[f].end(), in.trifacelist + 3 * f);
    in.trifacemarkerlist[f] = 1;
  }
  TetGenSettings s = settings;
  s.MaxVolume = -1; // the per-tet bounds say it
  Run(Switches("r", s, true), in, out);
  return Collect(out);
}

std::vector<double> TetVolumes(const TetGenMesh& mesh, double* total)
{
  std::vector<double> v(mesh.Tets.size() / 4);
  double sum = 0;
  for (size_t t = 0; t < v.size(); ++t)
  {
    v[t] = Six(mesh.Points.data(), &mesh.Tets[4 * t]) / 6.0;
    sum += v[t];
  }
  if (total)
  {
    *total = sum;
  }
  return v;
}
} // namespace art
