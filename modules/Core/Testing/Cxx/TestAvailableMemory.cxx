#include "AvailableMemory.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

namespace
{
double VmSizeBytes()
{
  std::ifstream in("/proc/self/status");
  std::string key;
  double kb = 0;
  while (in >> key)
  {
    if (key == "VmSize:")
    {
      in >> kb;
      return kb * 1024.0;
    }
  }
  return 0.0;
}
} // namespace

// What can be had, not the machine's total: MemAvailable is at most the physical memory.
TEST(AvailableMemory, AtMostThePhysicalMemory)
{
  const double total = double(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGESIZE);
  const double available = art::AvailableMemoryBytes();
  EXPECT_GT(available, 0.0);
  EXPECT_LE(available, total);
}

// An address-space limit (ulimit -v) lowers it to what is left under the limit.
TEST(AvailableMemory, FollowsAnAddressSpaceLimit)
{
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &old), 0);
  const double inUse = VmSizeBytes();
  ASSERT_GT(inUse, 0.0);
  rlimit capped = old;
  capped.rlim_cur = static_cast<rlim_t>(inUse + 1e9);
  if (old.rlim_max != RLIM_INFINITY && capped.rlim_cur > old.rlim_max)
  {
    GTEST_SKIP() << "the hard limit is below 1 GB above what is in use";
  }
  ASSERT_EQ(setrlimit(RLIMIT_AS, &capped), 0);
  const double available = art::AvailableMemoryBytes();
  ASSERT_EQ(setrlimit(RLIMIT_AS, &old), 0);
  EXPECT_GT(available, 0.8e9);
  EXPECT_LE(available, 1.0e9 + 1e6);
}
