// AvailableMemory: the memory a job can still have on this machine, for the checks that refuse a
// volume too large for it up front instead of being killed by the system half-way: MemAvailable
// (not the total), lowered to a cgroup's limit (a container) or an address-space limit (ulimit -v).
#ifndef art_AvailableMemory_h
#define art_AvailableMemory_h

#include "AdaptiveRTCoreModule.h"

namespace art
{
/// Bytes this process can still allocate: the least of /proc/meminfo's MemAvailable, a cgroup's
/// memory limit less its usage, and RLIMIT_AS less the address space in use; the machine's total
/// physical memory when none of these is known; 0 when even that is unknown.
ADAPTIVERTCORE_EXPORT double AvailableMemoryBytes();

/// Would work needing `needBytes` overrun `availableBytes` (AvailableMemoryBytes; 0 = unknown,
/// never)? A tenth of what is available is left for the rest of the run.
inline bool ExceedsAvailableMemory(double needBytes, double availableBytes)
{
  return availableBytes > 0 && needBytes > 0.9 * availableBytes;
}
} // namespace art

#endif
