// AtomicFile: write to a temporary file beside the target, then rename over it, so a reader (or
// a killed batch) never sees half a file and nothing the user had is lost on failure; Ctrl-C or
// a kill while it is open removes the temporary file too.
#ifndef art_AtomicFile_h
#define art_AtomicFile_h

#include "AdaptiveRTIOModule.h"

#include <string>

namespace art
{
class ADAPTIVERTIO_EXPORT AtomicFile
{
public:
  /// Chooses a unique temporary name in the target's folder, keeping its extension so that
  /// writers that pick a format by extension still work. Throws art::Error if the folder is
  /// missing or not writable. A target that is a symbolic link is written through (the file it
  /// points to is replaced, in that file's folder), and a replaced file keeps its permissions.
  explicit AtomicFile(std::string target);
  /// Removes the temporary file if Commit() was never called.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& TempPath() const { return Temp; }
  const std::string& Target() const { return Dest; }
  /// Renames the temporary file onto the target (atomic on one file system).
  void Commit();

private:
  std::string Dest, Temp;
  std::string Real; ///< Dest with symbolic links followed: the file replaced
  int Slot = -1; ///< where the temporary file is registered for removal on SIGINT/SIGTERM/SIGHUP
  bool Done = false;
};

/// Writes `content` to `path` atomically (temporary file, then rename). Throws art::Error.
ADAPTIVERTIO_EXPORT void WriteFileAtomic(const std::string& path, const std::string& content);

/// Extension of a path in lower case with its dot (".nii.gz" for double extensions), or "".
ADAPTIVERTIO_EXPORT std::string LowerExtension(const std::string& path);
} // namespace art

#endif
