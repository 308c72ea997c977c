// TriangleKernels: the watertight ray/triangle test (Woop, Benthin & Wald, JCGT 2013) over a
// batch of a voxel's triangles, in double: one at a time or 4 at once (AVX2), chosen at run time
// from what the processor has. Every lane does the scalar test's operations in its order (no
// fused multiply-add), so both give the same bits.
// Plain data only: the AVX2 file includes this header, and nothing of its may be merged into
// code that runs on a processor without those instructions.
#ifndef art_TriangleKernels_h
#define art_TriangleKernels_h

#include "AdaptiveRTTriangleGridModule.h"

#include <cstdint>

namespace art
{
/// What the test needs of a ray (Woop et al., section 3): the origin permuted so that kz is the
/// direction's largest axis, and the shear.
struct ShearedRay
{
  double Ox, Oy, Oz, Sx, Sy, Sz;
  int kx, ky, kz;
};

/// The nearest hit of a closest-hit query so far (record < 0: none).
struct NearestSoFar
{
  double t, u, v;
  long long record;
};

/// Hits of one batch, in the batch's order.
struct BatchHits
{
  double t[64], u[64], v[64];
  std::uint32_t record[64];
};

/// The batch tests. `records` is the store's records as 4 words each (vertex indices, plane),
/// `xyz` its float vertices; `ids` are n record indices (n <= 64).
struct TriangleKernel
{
  const char* name; ///< "scalar", "avx2 x4"
  int width;        ///< triangles tested at once
  /// Keeps the nearest hit with t in [tmin, best.t]; of equal t the lowest record.
  void (*closest)(const ShearedRay& r, const std::uint32_t* records, const float* xyz, const std::uint32_t* ids,
    int n, double tmin, NearestSoFar& best);
  /// True when any triangle is hit with t in [tmin, tmax].
  bool (*any)(const ShearedRay& r, const std::uint32_t* records, const float* xyz, const std::uint32_t* ids, int n,
    double tmin, double tmax);
  /// Every hit with t in [tmin, tmax]; returns how many were written to `out`.
  int (*all)(const ShearedRay& r, const std::uint32_t* records, const float* xyz, const std::uint32_t* ids, int n,
    double tmin, double tmax, BatchHits& out);
};

enum class TriangleTestIsa
{
  Best,   ///< AVX2 where the processor has it, else Scalar
  Scalar, ///< one triangle at a time
  AVX2    ///< 4 at a time (falls back to Scalar without AVX2)
};

/// The kernel for `isa`, or the widest below it that the processor (and the scene's size: the
/// gathers take 32-bit offsets) allows.
ADAPTIVERTTRIANGLEGRID_EXPORT const TriangleKernel& TriangleKernelFor(
  TriangleTestIsa isa, std::uint64_t records = 0, std::uint64_t points = 0);

/// The scalar kernel (baseline instructions only).
ADAPTIVERTTRIANGLEGRID_EXPORT const TriangleKernel& TriangleKernelScalar();
/// The AVX2 kernel, compiled in a file of its own with those instructions; null when the
/// compiler cannot build it.
const TriangleKernel* TriangleKernelAVX2();
} // namespace art

#endif
