#include "TriangleKernels.h"

#include "WatertightTest.h"

namespace art
{
namespace
{
const TriangleRecord* Records(const std::uint32_t* words)
{
  return reinterpret_cast<const TriangleRecord*>(words);
}

void ClosestScalar(const ShearedRay& r, const std::uint32_t* records, const float* xyz, const std::uint32_t* ids,
  int n, double tmin, NearestSoFar& best)
{
  ClosestOfBatch(r, Records(records), xyz, ids, n, tmin, best);
}

bool AnyScalar(const ShearedRay& r, const std::uint32_t* records, const float* xyz, const std::uint32_t* ids, int n,
  double tmin, double tmax)
{
  return AnyOfBatch(r, Records(records), xyz, ids, n, tmin, tmax);
}

int AllScalar(const ShearedRay& r, const std::uint32_t* records, const float* xyz, const std::uint32_t* ids, int n,
  double tmin, double tmax, BatchHits& out)
{
  return AllOfBatch(r, Records(records), xyz, ids, n, tmin, tmax, out);
}

const TriangleKernel Scalar = { "scalar", 1, ClosestScalar, AnyScalar, AllScalar };

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
bool HasAVX2()
{
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
}
#else
bool HasAVX2()
{
  return false;
}
#endif
} // namespace

const TriangleKernel& TriangleKernelScalar()
{
  return Scalar;
}

const TriangleKernel& TriangleKernelFor(TriangleTestIsa isa, std::uint64_t records, std::uint64_t points)
{
  static_assert(sizeof(TriangleRecord) == 4 * sizeof(std::uint32_t), "a record is four words");
  // The gathers take signed 32-bit element offsets: 4 per record, 3 per point.
  const bool fits = records < (1ull << 29) && points < (1ull << 31) / 3;
  static const bool avx2 = HasAVX2() && TriangleKernelAVX2();
  if (fits && avx2 && isa != TriangleTestIsa::Scalar)
  {
    return *TriangleKernelAVX2();
  }
  return Scalar;
}
} // namespace art
