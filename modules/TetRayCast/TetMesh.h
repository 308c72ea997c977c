// TetMesh: the compact arrays the cell-by-cell ray caster walks (Grosso, Luerig & Ertl 1997, sec. 5):
// positively oriented tets with their face links in one 32-byte record each (a walk step reads one
// record), each tet's linear interpolant f = a + g.x, volume-weighted vertex gradients, and the
// boundary faces with their planes and edge adjacency (for the entrance walk). Face i of a tet is
// the one opposite vertex i. Large meshes are laid out in Z-order, so that neighbours in space are
// neighbours in memory.
#ifndef art_TetMesh_h
#define art_TetMesh_h

#include "AdaptiveRTTetRayCastModule.h"
#include "Box3.h"

#include <array>
#include <string>
#include <vector>

class vtkImageData;
class vtkUnstructuredGrid;

namespace art
{
/// A tet as the walk reads it: its four vertex ids and its four face links (TetMesh::Link), in
/// one record aligned to half a cache line.
struct alignas(32) TetRecord
{
  std::array<int, 4> v;
  std::array<int, 4> link;
};

class ADAPTIVERTTETRAYCAST_EXPORT TetMesh
{
public:
  /// Vertices of face f (opposite vertex f), ordered counter-clockwise seen from outside.
  static constexpr int FaceVertex[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };

  struct Plane
  {
    Vec3 n;   ///< outward unit normal
    double d; ///< n.x = d on the face
  };

  TetMesh() = default;
  /// Builds from points, scalars and tets (4 point ids each, any orientation). Throws art::Error
  /// for out-of-range ids, non-finite values or inconsistent neighbours (a face in 3+ tets,
  /// overlapping tets on both sides of a face).
  TetMesh(std::vector<Vec3> points, std::vector<double> scalars, std::vector<std::array<int, 4>> tets);

  /// Full-resolution tets of a voxel volume: every voxel cell split into 5 tets (alternating, so
  /// the face diagonals match), point scalars = the voxel values (component 0).
  static TetMesh FromImage(vtkImageData* image, const std::string& file = {});
  /// Throws art::Error naming `file` when full-resolution tets would pass 2^29 or need more than
  /// 90% of availableBytes (FromImage passes art::AvailableMemoryBytes(); 0 = unknown, not checked).
  static void CheckFullResolutionFits(long long tets, double availableBytes, const std::string& file);
  /// Throws art::Error naming `file` when a mesh's cells, about `tets` once tetrahedralised, would
  /// need more than 90% of availableBytes (200 bytes a tet: the triangle filter's output and the
  /// engine's mesh; FromVTK passes art::AvailableMemoryBytes(); 0 = unknown, not checked).
  static void CheckMeshFits(long long tets, double availableBytes, const std::string& file);

  /// Any vtkUnstructuredGrid with point scalars (the active ones, or `array` by name). Cells
  /// other than tets are tetrahedralised first (vtkDataSetTriangleFilter), cells of lower
  /// dimension left out, points no tet uses dropped and duplicate points merged; `note` says so.
  static TetMesh FromVTK(vtkUnstructuredGrid* grid, const std::string& array = {},
    std::string* note = nullptr, const std::string& file = {});

  std::size_t NumberOfTets() const { return TetRecords.size(); }
  std::size_t NumberOfPoints() const { return Points.size(); }

  const std::vector<Vec3>& PointsArray() const { return Points; }
  const std::vector<double>& Scalars() const { return Values; }
  const std::array<int, 4>& Tet(std::size_t t) const { return TetRecords[t].v; }
  /// The tets across faces 0..3 of tet t (-1 on the boundary).
  std::array<int, 4> Neighbours(std::size_t t) const
  {
    const auto& l = TetRecords[t].link;
    return { LinkTet(l[0]), LinkTet(l[1]), LinkTet(l[2]), LinkTet(l[3]) };
  }
  /// Face f of tet t as a link: 4 * neighbour + the neighbour's face index of the shared face, or
  /// -1 on the boundary. The walker enters the neighbour knowing which of its faces it came through.
  int Link(std::size_t t, int f) const { return TetRecords[t].link[f]; }
  const std::array<int, 4>& LinkRow(std::size_t t) const { return TetRecords[t].link; }
  /// Every tet's record (the walk's default table).
  const TetRecord* Records() const { return TetRecords.data(); }
  const TetRecord& Record(std::size_t t) const { return TetRecords[t]; }
  static int LinkTet(int link) { return link < 0 ? -1 : link >> 2; }
  static int LinkFace(int link) { return link & 3; }
  /// Outward plane of face f of tet t. Computed from the vertices when asked: the Pluecker walker
  /// never needs planes, and storing four per tet would cost 128 bytes a tet (half a gigabyte for
  /// a full-resolution CT head); the boundary faces' planes are kept.
  Plane FacePlane(std::size_t t, int f) const;
  const Plane& BoundaryPlane(std::size_t b) const { return BPlanes[b]; }
  /// f(x) = c[0] + c[1] x + c[2] y + c[3] z inside tet t.
  const std::array<double, 4>& Interpolant(std::size_t t) const { return Interp[t]; }
  const Vec3& VertexGradient(int v) const { return Gradients[v]; }
  /// Barycentric weights of p in tet t (by sub-volumes; equal weights for a flat tet).
  void Barycentric(std::size_t t, const Vec3& p, double w[4]) const;
  /// The tet holding p, or -1: a walk across the face p lies beyond, then every tet when the walk
  /// leaves the mesh or circles.
  int Locate(const Vec3& p) const;
  double Evaluate(std::size_t t, const Vec3& p) const
  {
    const auto& c = Interp[t];
    return c[0] + c[1] * p.x + c[2] * p.y + c[3] * p.z;
  }

  /// Boundary face b is face BoundaryFace(b)[1] of tet BoundaryFace(b)[0].
  const std::vector<std::array<int, 2>>& BoundaryFaces() const { return Boundary; }
  /// The boundary face across edge k (vertices k, k+1 of FaceVertex order) of boundary face b.
  const std::array<int, 3>& BoundaryAdjacency(std::size_t b) const { return BoundaryAdj[b]; }

  const Box3& Bounds() const { return Box; }
  /// The range of the data the scalars stand for (presets and notes map onto it): the scalars'
  /// own, or for a reducer's output (field data scalar_range_min/max) its volume's, which the
  /// least-squares overshoot widens (a uint16 volume's mesh reached -2132 and looked like CT).
  double ScalarRange(int i) const { return Range[i]; }
  /// False for a mesh with holes, cavities, several pieces or a concave boundary.
  bool IsConvex() const { return Convex; }
  /// Largest edge length (VTK's pre-integration table is sized by it).
  double MaxEdge() const { return LongestEdge; }

  /// Meshes larger than this are renumbered in Z-order (points and tets) for cache locality;
  /// smaller ones keep the input numbering.
  static constexpr std::size_t LocalityThreshold = 65536;

private:
  /// Vertex -> incident tets in ascending tet order (CSR: Tets[First[i] .. First[i+1])).
  struct VertexTets
  {
    std::vector<int> First, Tets;
  };
  void CheckInput(const std::vector<std::array<int, 4>>& tets) const;
  void SortForLocality();
  VertexTets IncidentTets() const;
  std::vector<double> OrientAndInterpolate();
  void VertexGradients(const VertexTets& vt, const std::vector<double>& volume);
  void LinkFaces(const VertexTets& vt, const std::vector<double>& volume);
  void FindBoundary();
  void LinkBoundaryEdges();

  std::vector<Vec3> Points;
  std::vector<double> Values;
  std::vector<TetRecord> TetRecords;
  std::vector<Plane> BPlanes;
  std::vector<std::array<double, 4>> Interp;
  std::vector<Vec3> Gradients;
  std::vector<std::array<int, 2>> Boundary;
  std::vector<std::array<int, 3>> BoundaryAdj;
  Box3 Box;
  double Range[2] = { 0, 0 };
  double LongestEdge = 0;
  bool Convex = true;
};
} // namespace art

#endif
