// RegularFile: checks that a path a program is about to read names a regular file it may open,
// without blocking: a FIFO is opened with O_NONBLOCK and refused after fstat, so no read can
// wait forever on it, and a device (/dev/zero linked as a volume) is refused before any read.
// The errors say what the system said (permission denied is not "no such file").
#ifndef art_RegularFile_h
#define art_RegularFile_h

#include "Error.h"

#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace art
{
/// What kind of file `mode` is, for "is a FIFO, not a regular file".
inline const char* FileTypeName(mode_t mode)
{
  return S_ISDIR(mode) ? "a directory" : S_ISFIFO(mode) ? "a FIFO (named pipe)" : S_ISCHR(mode) ? "a character device"
    : S_ISBLK(mode) ? "a block device" : S_ISSOCK(mode) ? "a socket" : "not a regular file";
}

/// Why `path` cannot be opened for reading as a regular file, or "" when it can. Directories are
/// allowed when `allowDirectory`. `emptyIsError` also refuses a file of no bytes.
inline std::string RegularFileProblem(const std::string& path, bool allowDirectory = false, bool emptyIsError = true)
{
  if (path.empty())
  {
    return "empty file name";
  }
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
  {
    const int e = errno;
    struct stat link;
    if (e == ENOENT && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode))
    {
      return "is a broken symbolic link (the file it points to does not exist)";
    }
    if (e == ENOENT)
    {
      return "no such file or directory";
    }
    if (e == EACCES)
    {
      return "permission denied (a folder on its path cannot be searched)";
    }
    return std::string("cannot open: ") + std::strerror(e);
  }
  if (S_ISDIR(st.st_mode))
  {
    if (!allowDirectory)
    {
      return "is a directory, expected a file";
    }
    return ::access(path.c_str(), R_OK | X_OK) == 0 ? "" : "permission denied (the folder cannot be read)";
  }
  if (!S_ISREG(st.st_mode))
  {
    return std::string("is ") + FileTypeName(st.st_mode) + ", not a regular file";
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
  {
    const int e = errno;
    return e == EACCES ? "permission denied" : std::string("cannot open: ") + std::strerror(e);
  }
  struct stat opened;
  const bool regular = ::fstat(fd, &opened) == 0 && S_ISREG(opened.st_mode);
  ::close(fd);
  if (!regular)
  {
    return "is not a regular file";
  }
  if (emptyIsError && opened.st_size == 0)
  {
    return "file is empty";
  }
  return "";
}

/// Throws art::Error naming `path` unless it is a regular file that can be opened for reading.
inline void RequireRegularFile(const std::string& path, bool allowDirectory = false, bool emptyIsError = true)
{
  const std::string problem = RegularFileProblem(path, allowDirectory, emptyIsError);
  if (!problem.empty())
  {
    throw Error(problem, path == "" ? std::string() : path);
  }
}
} // namespace art

#endif
