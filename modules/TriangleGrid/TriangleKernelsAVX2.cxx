// The batch triangle test 4 triangles at a time with AVX2 (this file is compiled with -mavx2;
// TriangleKernelFor calls it only on a processor that has AVX2).
#include "TriangleKernels.h"

#if defined(__AVX2__)
#include <immintrin.h>

#include "TriangleKernelsSimd.h"

namespace
{
struct Avx2Lanes
{
  static constexpr int W = 4;
  using D = __m256d;
  using I = __m128i;
  static I Ids(const std::uint32_t* ids, int m)
  {
    if (m == 4)
    {
      return _mm_loadu_si128(reinterpret_cast<const __m128i*>(ids));
    }
    const int first = static_cast<int>(ids[0]);
    return _mm_setr_epi32(first, m > 1 ? static_cast<int>(ids[1]) : first, m > 2 ? static_cast<int>(ids[2]) : first, first);
  }
  static I Times4(I i) { return _mm_slli_epi32(i, 2); }
  static I Times3(I i) { return _mm_add_epi32(_mm_slli_epi32(i, 1), i); }
  static I Plus(I i, int k) { return _mm_add_epi32(i, _mm_set1_epi32(k)); }
  static I Gather(const std::uint32_t* base, I index)
  {
    return _mm_i32gather_epi32(reinterpret_cast<const int*>(base), index, 4);
  }
  static D Coords(const float* xyz, I index) { return _mm256_cvtps_pd(_mm_i32gather_ps(xyz, index, 4)); }
  static D Set(double x) { return _mm256_set1_pd(x); }
  static unsigned Lt(D a, D b) { return static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_LT_OQ))); }
  static unsigned Gt(D a, D b) { return static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_GT_OQ))); }
  static unsigned Eq(D a, D b) { return static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_EQ_OQ))); }
  static unsigned Ge(D a, D b) { return static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_GE_OQ))); }
  static unsigned Le(D a, D b) { return static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_LE_OQ))); }
  static void Store(double* p, D d) { _mm256_store_pd(p, d); }
};

const art::TriangleKernel Kernel = { "avx2 x4", 4, ClosestLanes<Avx2Lanes>, AnyLanes<Avx2Lanes>, AllLanes<Avx2Lanes> };
} // namespace

const art::TriangleKernel* art::TriangleKernelAVX2()
{
  return &Kernel;
}
#else
const art::TriangleKernel* art::TriangleKernelAVX2()
{
  return nullptr;
}
#endif
