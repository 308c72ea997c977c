#include "AvailableMemory.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

namespace art
{
namespace
{
// A "Key:  123 kB" line of a /proc file, in bytes; < 0 when absent.
double ProcField(const char* path, const std::string& key)
{
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.compare(0, key.size(), key) == 0 && line.size() > key.size() && line[key.size()] == ':')
    {
      std::istringstream s(line.substr(key.size() + 1));
      double v = -1;
      std::string unit;
      s >> v >> unit;
      return v < 0 ? -1.0 : (unit == "kB" ? v * 1024.0 : v);
    }
  }
  return -1.0;
}

// One number from a cgroup file; < 0 when absent or "max" (no limit).
double CgroupNumber(const std::string& path)
{
  std::ifstream in(path);
  std::string word;
  if (!(in >> word) || word == "max")
  {
    return -1.0;
  }
  try
  {
    return std::stod(word);
  }
  catch (...)
  {
    return -1.0;
  }
}

// What the process's cgroup (v2, else v1's memory controller) leaves under its limit; < 0 without one.
double CgroupHeadroom()
{
  std::ifstream cg("/proc/self/cgroup");
  std::string line;
  while (std::getline(cg, line))
  {
    const auto colon = line.find(':'), second = line.find(':', colon + 1);
    if (colon == std::string::npos || second == std::string::npos)
    {
      continue;
    }
    const std::string controllers = line.substr(colon + 1, second - colon - 1), path = line.substr(second + 1);
    std::string dir;
    if (line.compare(0, 2, "0:") == 0 && controllers.empty())
    {
      dir = "/sys/fs/cgroup" + path;
    }
    else if (controllers.find("memory") != std::string::npos)
    {
      dir = "/sys/fs/cgroup/memory" + path;
    }
    else
    {
      continue;
    }
    double limit = CgroupNumber(dir + "/memory.max"), used = CgroupNumber(dir + "/memory.current");
    if (limit < 0)
    {
      limit = CgroupNumber(dir + "/memory.limit_in_bytes"); // v1; "no limit" is a huge number
      used = CgroupNumber(dir + "/memory.usage_in_bytes");
    }
    if (limit > 0 && limit < 1e18)
    {
      return std::max(0.0, limit - std::max(0.0, used));
    }
  }
  return -1.0;
}
} // namespace

double AvailableMemoryBytes()
{
  double bytes = ProcField("/proc/meminfo", "MemAvailable");
  if (bytes < 0)
  {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
    bytes = pages > 0 && pageSize > 0 ? double(pages) * pageSize : 0.0;
  }
  const double cgroup = CgroupHeadroom();
  if (cgroup >= 0 && (bytes <= 0 || cgroup < bytes))
  {
    bytes = cgroup;
  }
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
  {
    const double inUse = std::max(0.0, ProcField("/proc/self/status", "VmSize"));
    const double left = std::max(0.0, double(as.rlim_cur) - inUse);
    if (bytes <= 0 || left < bytes)
    {
      bytes = left;
    }
  }
  return bytes;
}
} // namespace art
