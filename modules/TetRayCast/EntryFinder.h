// EntryFinder: the boundary faces a ray enters a tet mesh through (Grosso, Luerig & Ertl 1997,
// sec. 5, ray entrance). Per frame, the boundary faces that face the camera are sorted into
// 8x8-pixel screen buckets, each bucket's faces by their nearest depth. A convex mesh has one
// entry face per ray: the previous ray's entry face (scan lines run in alternating directions, so
// it is the neighbouring pixel's) and its boundary neighbours are tried first, the bucket only
// when that walk fails. A non-convex mesh (or region) needs every entry face along the ray in t
// order: an EntryCursor hands them out as the walk asks for them, testing a bucket's faces only
// up to the depth of the nearest entry found, so faces behind it wait until the ray gets there
// (with early termination most rays never do). Or, when given, the TriangleGrid all-hits query
// over the boundary triangles is used instead; see TetRayCaster.
#ifndef art_EntryFinder_h
#define art_EntryFinder_h

#include "AdaptiveRTTetRayCastModule.h"
#include "Camera.h"
#include "Counters.h"
#include "TetMesh.h"
#include "ProjectedWalker.h"
#include "TetWalker.h"

#include <vector>

namespace art
{
struct Entry
{
  int face; ///< index into the finder's faces (the mesh's boundary faces unless given others)
  FaceCrossing x;
};

class EntryFinder;

/// A face in one of EntryFinder's screen buckets: its pixel box (with slack), nearest depth along
/// the view and vertices (outward order), inline so that a bucket's scan reads memory in order.
struct EntrySlot
{
  float x0, x1, y0, y1, z;
  int face;
  int v[3];
};

/// One ray's entries in t order (EntryFinder::Start), found as they are asked for, or a list
/// already sorted (List).
class ADAPTIVERTTETRAYCAST_EXPORT EntryCursor
{
public:
  /// The next entry in t order, not taken; null when there is none.
  const Entry* Front()
  {
    if (Next != End)
    {
      Scan();
    }
    return Head < Pending.size() ? &Pending[Head] : nullptr;
  }
  void Pop() { ++Head; }
  /// A list sorted by t, for a source that finds every entry at once.
  std::vector<Entry>& List()
  {
    Head = 0;
    Next = End = nullptr;
    return Pending;
  }

private:
  friend class EntryFinder;
  void Scan();
  void Insert(const Entry& e);

  std::vector<Entry> Pending; ///< found, sorted by t from Head on
  std::size_t Head = 0;
  const EntryFinder* F = nullptr;
  const TetWalker* W = nullptr;
  const ProjectedWalker* PW = nullptr;
  const EntrySlot* Next = nullptr; ///< the bucket's faces not yet tested
  const EntrySlot* End = nullptr;
  float Fx = 0, Fy = 0;
  double TMin = 0, Z0 = 0, InvDz = 0, Slack = 0;
  bool Prune = false;
  /// Slots deeper than this lie behind the next entry found (ZStop's depth rule); +inf for none.
  double ZStop = 0;
  void UpdateStop();
};

class ADAPTIVERTTETRAYCAST_EXPORT EntryFinder
{
public:
  /// Buckets for `cam`'s pixels. `faces` (tet, face), when given, replaces the mesh's boundary
  /// faces: the faces of a region the rays enter (TetRayCaster's visible tets); every entry is
  /// then asked for (Find's `all`). It must outlive the finder.
  EntryFinder(const TetMesh& m, const Camera& cam, const std::vector<std::array<int, 2>>* faces = nullptr);
  /// Without a camera: every boundary face is tested for every ray (tests, single rays).
  explicit EntryFinder(const TetMesh& m);

  /// The entry crossings of ray r (through pixel px, py when bucketed), sorted by t, with
  /// t >= r.tmin. `all` asks for every one (non-convex); otherwise the first one found suffices
  /// (convex). `hint` is the previous ray's entry face, updated (-1: none).
  /// `pw`, when given (a camera ray in a valid ProjectedView), tests the faces in 2-D.
  void Find(const TetWalker& w, const Ray& r, int px, int py, bool all, std::vector<Entry>& out,
    int& hint, Counters& c, const ProjectedWalker* pw = nullptr) const;

  /// Every entry of ray r through pixel px, py, handed out by `cur` in t order as they are asked
  /// for (the whole bucket is tested only when the ray gets past its faces).
  void Start(EntryCursor& cur, const TetWalker& w, const Ray& r, int px, int py, Counters& c,
    const ProjectedWalker* pw = nullptr) const;

  /// True when no ray through the pixels [x0, x1) x [y0, y1) can find an entry: their buckets
  /// are empty and no face is tested by every ray.
  bool Empty(int x0, int y0, int x1, int y1) const;

  /// Faces every ray tests (across the eye's plane, or all without a camera).
  std::size_t GlobalCount() const { return Global.size(); }

private:
  friend class EntryCursor;
  bool Test(const TetWalker& w, const ProjectedWalker* pw, double tmin, int b, Entry& e) const;
  bool Test(const TetWalker& w, const ProjectedWalker* pw, double tmin, const EntrySlot& sl, Entry& e) const;

  const TetMesh& M;
  const std::vector<std::array<int, 2>>& F; ///< the faces entered through
  bool Region = false;                      ///< F is not the mesh's boundary (no adjacency)
  int W = 0, H = 0, BW = 0, BH = 0;
  bool Bucketed = false;
  Vec3 Eye, Fwd;            ///< depth is (p - Eye) . Fwd
  double DepthMargin = 0;   ///< 1e-9 of the mesh's size: the cursor's slack in depth, once a frame
  std::vector<int> Begin;   ///< CSR: bucket k's faces are Slots[Begin[k] .. Begin[k+1]), nearest first
  std::vector<EntrySlot> Slots;
  std::vector<int> Global;  ///< faces every ray must test (behind the eye, or no camera)
};
} // namespace art

#endif
