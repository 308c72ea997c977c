// EntryFinder: the boundary faces a ray enters a tet mesh through (Grosso, Luerig & Ertl 1997,
// sec. 5, ray entrance). Per frame, the boundary faces that face the camera are sorted into
// 8x8-pixel screen buckets. A convex mesh has one entry face per ray: the previous ray's entry face
// (scan lines run in alternating directions, so it is the neighbouring pixel's) and its boundary
// neighbours are tried first, the bucket only when that walk fails. A non-convex mesh needs every
// entry face along the ray, sorted by t: all of the bucket's faces are tested (or, when given, the
// TriangleGrid all-hits query over the boundary triangles is used instead; see TetRayCaster).
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

  /// True when no ray through the pixels [x0, x1) x [y0, y1) can find an entry: their buckets
  /// are empty and no face is tested by every ray.
  bool Empty(int x0, int y0, int x1, int y1) const;

  /// Faces every ray tests (across the eye's plane, or all without a camera).
  std::size_t GlobalCount() const { return Global.size(); }

private:
  bool Test(const TetWalker& w, const ProjectedWalker* pw, const Ray& r, int b, Entry& e) const;

  const TetMesh& M;
  const std::vector<std::array<int, 2>>& F; ///< the faces entered through
  bool Region = false;                      ///< F is not the mesh's boundary (no adjacency)
  int W = 0, H = 0, BW = 0, BH = 0;
  bool Bucketed = false;
  std::vector<int> Start, Faces; ///< CSR: faces of bucket k are Faces[Start[k] .. Start[k+1])
  std::vector<int> Global;       ///< faces every ray must test (behind the eye, or no camera)
  std::vector<std::array<float, 4>> Box; ///< each bucketed face's pixel box x0, x1, y0, y1, with slack
};
} // namespace art

#endif
