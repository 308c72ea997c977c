#include "batch/FrameClaim.h"

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <fstream>
#include <string>
#include <unistd.h>

namespace cli
{
namespace
{
std::string Host()
{
  char h[256] = {};
  gethostname(h, sizeof h - 1);
  return h;
}

// A lock is stale when it names this host and a process that no longer exists, or when it
// is still empty a minute after it was made (its writer died between create and write).
bool Stale(const std::string& path)
{
  std::ifstream in(path);
  std::string host;
  long pid = 0;
  if (!(in >> host >> pid))
  {
    std::error_code ec;
    const auto age = std::filesystem::file_time_type::clock::now() - std::filesystem::last_write_time(path, ec);
    return !ec && age > std::chrono::minutes(1);
  }
  return host == Host() && pid > 0 && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}
}

FrameClaim::FrameClaim(std::string lockPath)
  : Path(std::move(lockPath))
{
  Mine = TryCreate();
  if (!Mine && Stale(Path))
  {
    std::remove(Path.c_str());
    Mine = TryCreate();
  }
}

bool FrameClaim::TryCreate()
{
  const int fd = open(Path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0)
  {
    return false;
  }
  const std::string who = Host() + " " + std::to_string(getpid()) + "\n";
  const bool ok = write(fd, who.data(), who.size()) == static_cast<ssize_t>(who.size());
  close(fd);
  return ok;
}

FrameClaim::~FrameClaim()
{
  if (Mine)
  {
    std::remove(Path.c_str());
  }
}
} // namespace cli
