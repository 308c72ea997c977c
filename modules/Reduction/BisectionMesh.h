// BisectionMesh: a conforming tetrahedral mesh of a box refined by newest-vertex bisection.
// Kuhn/Freudenthal split of a coarse grid of boxes (6 tets each), then Maubach's tagged bisection
// (Maubach 1995; Arnold, Mukherjee & Pouly 2000) with recursive conforming closure, or, instead,
// free edge splits: any chosen edge cut at its midpoint or a quarter point together with its
// whole star (always conforming).
#ifndef art_BisectionMesh_h
#define art_BisectionMesh_h

#include "AdaptiveRTReductionModule.h"

#include <array>
#include <cstdint>
#include <vector>

namespace art
{
/// A mesh vertex on an exact lattice: voxel index coordinates times 2^ScaleBits. Coarse corners
/// sit on voxel centres and every bisection midpoint (or checked quarter point) stays exact, so the voxel-in-tet test can be
/// done in integer arithmetic and each voxel centre belongs to exactly one tet.
struct LatticePoint
{
  int64_t x = 0, y = 0, z = 0;
  int64_t operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

class ADAPTIVERTREDUCTION_EXPORT BisectionMesh
{
public:
  static constexpr int ScaleBits = 16;
  static constexpr int64_t Scale = int64_t(1) << ScaleBits;

  /// Kuhn split of cubes[0] x cubes[1] x cubes[2] boxes covering voxel indices [0, dims-1];
  /// box corners are rounded to voxel centres. Every tet starts with tag 3 (refinement edge =
  /// its box's main diagonal), which Maubach shows is a compatible initial tagging.
  void InitKuhn(const int dims[3], const int cubes[3]);
  /// A mesh made elsewhere (TetGen's, of a closed surface; MMG's anisotropic remeshing), its
  /// vertices on the lattice: outside the bisection hierarchy, so Refine and SplitEdge are refused. Throws art::Error when a tet
  /// names a vertex that does not exist.
  void InitFromTets(std::vector<LatticePoint> points, const std::vector<std::array<int, 4>>& tets);

  int NumberOfTets() const { return static_cast<int>(Tets.size()); }
  int NumberOfVertices() const { return static_cast<int>(Verts.size()); }
  const std::array<int, 4>& Tet(int t) const { return Tets[t]; }
  const LatticePoint& Vertex(int v) const { return Verts[v]; }
  /// For a vertex made by bisection, the two ends of the edge it halves (-1 for coarse corners).
  const std::array<int, 2>& Parents(int v) const { return Parent[v]; }
  /// Where v sits on its parents' edge: the weight of Parents(v)[1], in quarters (2: the midpoint).
  int ParentQuarters(int v) const { return Quarter[v]; }
  /// Bumped each time slot t is replaced (a stale reference to t can tell).
  uint32_t Version(int t) const { return Versions[t]; }
  /// Number of bisections from the coarse tet.
  int Generation(int t) const { return Gen[t]; }
  /// Tets that have v as a corner.
  const std::vector<int>& TetsAround(int v) const { return VertexTets[v]; }

  /// Bisects t and, first, whatever neighbours must be bisected so the mesh stays conforming.
  /// Slots of replaced tets and new tets are appended to `touched` (may repeat).
  void Refine(int t, std::vector<int>& touched);
  /// True when the refinement edge of t can still be halved exactly on the lattice.
  bool CanBisect(int t) const;
  /// Squared length of t's refinement edge in voxel index units.
  double RefinementEdgeLength2(int t) const;

  /// The six edges of a tet as pairs of corner positions 0..3.
  static const int EdgeCorners[6][2];
  /// Squared length of the edge (a, b) in voxel index units.
  double EdgeLength2(int a, int b) const;
  /// True when the point `quarters` / 4 of the way from a to b (1, 2 or 3) lies on the lattice.
  bool CanSplitEdge(int a, int b, int quarters = 2) const;
  /// Splits the edge (a, b) (vertex ids) and every tet around it at one point: conforming
  /// whatever edge is chosen, and each child keeps its parent's orientation. Replaced and new tet
  /// slots are appended to `touched`. Once used, Refine (Maubach's tags) is refused: the tags no
  /// longer describe a compatible bisection. Throws when the midpoint is off the lattice.
  /// `quarters` (1..3) puts the new vertex that far from a toward b instead of at the midpoint.
  void SplitEdge(int a, int b, std::vector<int>& touched, int quarters = 2);
  /// Tets that have both a and b as corners, ascending.
  void TetsWithEdge(int a, int b, std::vector<int>& out) const;

  /// Puts vertex v at p (any lattice point; VertexRelocator checks that no tet around it flips
  /// or flattens) and bumps the versions of its tets. The mesh then leaves the bisection
  /// hierarchy: Refine and SplitEdge are refused afterwards (call StopRefinement first when
  /// moving vertices with no tet in common from several threads).
  void MoveVertex(int v, const LatticePoint& p);
  void StopRefinement() { Moved = true; }

private:
  std::array<int, 2> RefinementEdge(int t) const;
  void Bisect(int t, int mid, std::vector<int>& touched);
  void RefineRecursive(int t, std::vector<int>& touched, int depth);

  std::vector<LatticePoint> Verts;
  std::vector<std::array<int, 2>> Parent;
  std::vector<uint8_t> Quarter;
  std::vector<std::array<int, 4>> Tets; // Maubach order x0..x3
  std::vector<uint8_t> Tag;             // k in 1..3: refinement edge is (x0, xk)
  std::vector<uint16_t> Gen;
  std::vector<uint32_t> Versions;
  std::vector<std::vector<int>> VertexTets; // tets around each vertex, for edge patches
  bool EdgeSplits = false;                  // SplitEdge was used: the Maubach tags are void
  bool Moved = false;                       // MoveVertex was used: no more refinement
};
} // namespace art

#endif
