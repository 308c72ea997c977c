#include "AtomicFile.h"
#include "Error.h"
#include "RegularFile.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace art
{
std::string LowerExtension(const std::string& path)
{
  std::string name = fs::path(path).filename().string();
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* twoPart : { ".nii.gz", ".vtk.gz" })
  {
    const std::string e(twoPart);
    if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0)
    {
      return e;
    }
  }
  const auto dot = name.rfind('.');
  return (dot == std::string::npos || dot == 0) ? std::string() : name.substr(dot);
}

namespace
{
// Temporary files being written, so that Ctrl-C (or a kill) does not leave a hidden half-written
// ".name.tmpPID-N.ext" beside the target. Fixed storage: the handler may only read memory and
// call async-signal-safe functions (unlink, signal, raise).
constexpr int MaxLive = 64;
char LivePath[MaxLive][4096];
std::atomic<int> LiveState[MaxLive]; // 0 free, 1 being changed, 2 a temporary file to remove

void RemoveLiveAndReraise(int sig)
{
  for (int i = 0; i < MaxLive; ++i)
  {
    if (LiveState[i].load() == 2)
    {
      unlink(LivePath[i]);
    }
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// Only where the signal still has its default action: a host (Python, a GUI) keeps its own.
void InstallHandlersOnce()
{
  static const bool installed = [] {
    for (int sig : { SIGINT, SIGTERM, SIGHUP })
    {
      struct sigaction old = {};
      if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_DFL)
      {
        struct sigaction sa = {};
        sa.sa_handler = RemoveLiveAndReraise;
        sigemptyset(&sa.sa_mask);
        sigaction(sig, &sa, nullptr);
      }
    }
    return true;
  }();
  (void)installed;
}

int RegisterLive(const std::string& path)
{
  if (path.size() >= sizeof LivePath[0])
  {
    return -1;
  }
  for (int i = 0; i < MaxLive; ++i)
  {
    int expected = 0;
    if (LiveState[i].compare_exchange_strong(expected, 1))
    {
      std::memcpy(LivePath[i], path.c_str(), path.size() + 1);
      LiveState[i].store(2);
      return i;
    }
  }
  return -1; // more than MaxLive files at once: the destructor still removes it
}

void UnregisterLive(int slot)
{
  if (slot >= 0)
  {
    LiveState[slot].store(0);
  }
}
} // namespace

namespace
{
// An existing file is replaced only when the user could write it: a write-protected (0444)
// result was replaced without a word (as root too, whom access() lets write anything), and a
// device or FIFO named as the output (/dev/null) would have been replaced by a plain file.
void RefuseToReplace(const std::string& real, const std::string& dest)
{
  struct stat st;
  if (::lstat(real.c_str(), &st) != 0)
  {
    return; // a new file
  }
  if (!S_ISREG(st.st_mode))
  {
    throw Error(std::string("exists and is ") + FileTypeName(st.st_mode) + ", not a regular file: not replaced", dest);
  }
  if ((st.st_mode & 0222) == 0 || ::access(real.c_str(), W_OK) != 0)
  {
    throw Error("exists and is write-protected: not replaced (make it writable or remove it first)", dest);
  }
}
} // namespace

AtomicFile::AtomicFile(std::string target)
  : Dest(std::move(target))
{
  static std::atomic<int> serial{ 0 };
  std::error_code ec;
  // A symbolic link is written through, as a shell's '>' does: renaming onto the link itself
  // replaced it with a plain file and left the file it pointed to as it was.
  fs::path p(Dest);
  for (int hops = 0; hops < 40 && fs::is_symlink(p, ec); ++hops)
  {
    const fs::path to = fs::read_symlink(p, ec);
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  Real = p.string();
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec))
  {
    // A file where the folder should be (out.png/x.png with out.png a file) is not a missing folder.
    throw Error(fs::exists(dir, ec) ? "'" + dir.string() + "' is a file, not a folder"
                                    : "folder '" + dir.string() + "' does not exist",
      Dest);
  }
  if (fs::is_directory(p, ec))
  {
    throw Error("is a directory, expected a file name", Dest);
  }
  RefuseToReplace(Real, Dest);
  if (access(dir.c_str(), W_OK) != 0)
  {
    throw Error("folder '" + dir.string() + "' is not writable", Dest);
  }
  const std::string ext = LowerExtension(Dest);
  Temp = (dir / ("." + p.filename().string() + ".tmp" + std::to_string(getpid()) + "-" +
            std::to_string(serial++) + ext))
           .string();
  // Created here, so that a folder no file can be made in (read-only file system, root in /proc)
  // says why: VTK's image writers reported it as "OutOfDiskSpaceError".
  const int fd = ::open(Temp.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0666);
  if (fd < 0)
  {
    throw Error("cannot create a file in folder '" + dir.string() + "': " + std::strerror(errno), Dest);
  }
  ::close(fd);
  InstallHandlersOnce();
  Slot = RegisterLive(Temp);
}

AtomicFile::~AtomicFile()
{
  if (!Done)
  {
    std::remove(Temp.c_str());
  }
  UnregisterLive(Slot);
}

void WriteFileAtomic(const std::string& path, const std::string& content)
{
  AtomicFile file(path);
  {
    std::ofstream out(file.TempPath(), std::ios::binary);
    out << content;
    out.flush();
    if (!out)
    {
      throw Error("cannot write file", path);
    }
  }
  file.Commit();
}

void AtomicFile::Commit()
{
  // The file replaced keeps its permissions (a group-writable result stays group-writable).
  std::error_code ec;
  const fs::file_status old = fs::status(Real, ec);
  if (!ec && fs::is_regular_file(old))
  {
    fs::permissions(Temp, old.permissions(), ec);
  }
  if (std::rename(Temp.c_str(), Real.c_str()) != 0)
  {
    const std::string why = std::strerror(errno);
    std::remove(Temp.c_str());
    Done = true;
    throw Error("cannot replace file: " + why, Dest);
  }
  Done = true;
}
} // namespace art
