// MeshCache: `render --mesh-cache DIR` keeps each reduced mesh on disk, so renders of one volume
// with the same reduction settings (a batch's frames: other cameras, sizes, integrators) reduce it
// once. An entry is keyed by the voxels as loaded (grid, placement, name and a 128-bit hash of
// the samples: a changed file, a detached .raw or a DICOM folder are all covered), every
// ReducerOptions field, and the files of this program and of the reducer library (a rebuilt tool
// never reuses an old entry). Entries are .vtu files (ParaView and any VTK reader open them) with
// the key in their field data, written atomically; one that is damaged or was made for another
// key is a miss.
#ifndef adaptivert_MeshCache_h
#define adaptivert_MeshCache_h

#ifdef ART_HAVE_Reduction
#include "TetReducer.h"
#include "VoxelVolume.h"

#include <string>

namespace cli
{
class MeshCache
{
public:
  MeshCache(const std::string& dir, const art::VoxelVolume& volume, const art::ReducerOptions& options);

  /// The entry's file, DIR/<hash>.vtu.
  const std::string& File() const { return Path; }
  /// True, with `out` filled, when the entry exists, is whole and was made for this key.
  bool Load(art::ReducedMesh& out) const;
  /// Writes the entry (creating DIR); throws art::Error naming the file when it cannot.
  void Store(const art::ReducedMesh& m) const;

private:
  std::string Key, Path;
};
} // namespace cli
#endif

#endif
