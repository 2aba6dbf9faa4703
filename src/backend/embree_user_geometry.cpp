#include "embree_user_geometry.h"

#include "rtpro/core/avx2_clones.h"

#include <emmintrin.h>

namespace rtpro {

RTPRO_AVX2_CLONES std::uint32_t valid_lanes(const int* valid, unsigned n) {
  if (n == 8) {  // Embree's packets of eight: one compare
    const __m128i minus_one = _mm_set1_epi32(-1);
    const __m128i low = _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(valid)), minus_one);
    const __m128i high = _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(valid + 4)), minus_one);
    return static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(low)) | _mm_movemask_ps(_mm_castsi128_ps(high))
                                                                                   << 4);
  }
  std::uint32_t active = 0;
  for (unsigned i = 0; i < n; ++i)
    if (valid[i] == -1) active |= 1u << i;
  return active;
}

}  // namespace rtpro
