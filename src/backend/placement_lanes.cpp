#include "placement_lanes.h"

#include "rtpro/scene/motion.h"

#include <immintrin.h>

#include <span>

namespace rtpro {

namespace {

// |v| < infinity, lane by lane: false for NaN and infinities, as std::isfinite.
[[gnu::target("avx2")]] __m256d finite_lanes(__m256d v) {
  return _mm256_cmp_pd(_mm256_andnot_pd(_mm256_set1_pd(-0.0), v), _mm256_set1_pd(__builtin_inf()), _CMP_LT_OQ);
}
[[gnu::target("avx2")]] __m128 finite_lanes(__m128 v) {
  return _mm_cmp_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f), v), _mm_set1_ps(__builtin_inff()), _CMP_LT_OQ);
}

[[gnu::target("avx2"), gnu::always_inline]] inline __m256d mul(__m256d a, __m256d b) { return _mm256_mul_pd(a, b); }
[[gnu::target("avx2"), gnu::always_inline]] inline __m256d sub(__m256d a, __m256d b) { return _mm256_sub_pd(a, b); }
// a * b - c * d, as inverse() writes each cofactor.
[[gnu::target("avx2"), gnu::always_inline]] inline __m256d cofactor(__m256d a, __m256d b, __m256d c, __m256d d) {
  return sub(mul(a, b), mul(c, d));
}

}  // namespace

[[gnu::target("avx2")]] unsigned world_to_object_lanes(const Instance& instance, const float* times, unsigned count,
                                                       Affine* out) {
  Affine to_world[kPlacementLanes];
  for (unsigned k = 0; k < kPlacementLanes; ++k)
    to_world[k] =
        value_at_time<Affine>(std::span<const Affine>(instance.object_to_world_steps), times[k < count ? k : 0]);
  __m128 lanes[3][4];  // each entry of the four matrices
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      lanes[i][j] = _mm_setr_ps(to_world[0].m[i][j], to_world[1].m[i][j], to_world[2].m[i][j], to_world[3].m[i][j]);
  __m256d l[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) l[i][j] = _mm256_cvtps_pd(lanes[i][j]);

  const __m256d det = _mm256_add_pd(sub(mul(l[0][0], cofactor(l[1][1], l[2][2], l[1][2], l[2][1])),
                                        mul(l[0][1], cofactor(l[1][0], l[2][2], l[1][2], l[2][0]))),
                                    mul(l[0][2], cofactor(l[1][0], l[2][1], l[1][1], l[2][0])));
  // std::max(scale, |v|) keeps scale where v is NaN; maxpd returns its second operand then.
  __m256d scale = _mm256_setzero_pd();
  for (const auto& row : l)
    for (const __m256d v : row) scale = _mm256_max_pd(_mm256_andnot_pd(_mm256_set1_pd(-0.0), v), scale);
  const __m256d threshold = mul(mul(mul(_mm256_set1_pd(1e-12), scale), scale), scale);
  const __m256d absolute_det = _mm256_andnot_pd(_mm256_set1_pd(-0.0), det);
  __m256d regular = _mm256_and_pd(finite_lanes(det), _mm256_cmp_pd(scale, _mm256_setzero_pd(), _CMP_NEQ_OQ));
  regular = _mm256_and_pd(regular, _mm256_cmp_pd(absolute_det, threshold, _CMP_NLE_UQ));

  __m256d inv[3][3];
  inv[0][0] = _mm256_div_pd(cofactor(l[1][1], l[2][2], l[1][2], l[2][1]), det);
  inv[0][1] = _mm256_div_pd(cofactor(l[0][2], l[2][1], l[0][1], l[2][2]), det);
  inv[0][2] = _mm256_div_pd(cofactor(l[0][1], l[1][2], l[0][2], l[1][1]), det);
  inv[1][0] = _mm256_div_pd(cofactor(l[1][2], l[2][0], l[1][0], l[2][2]), det);
  inv[1][1] = _mm256_div_pd(cofactor(l[0][0], l[2][2], l[0][2], l[2][0]), det);
  inv[1][2] = _mm256_div_pd(cofactor(l[0][2], l[1][0], l[0][0], l[1][2]), det);
  inv[2][0] = _mm256_div_pd(cofactor(l[1][0], l[2][1], l[1][1], l[2][0]), det);
  inv[2][1] = _mm256_div_pd(cofactor(l[0][1], l[2][0], l[0][0], l[2][1]), det);
  inv[2][2] = _mm256_div_pd(cofactor(l[0][0], l[1][1], l[0][1], l[1][0]), det);

  __m128 finite = _mm_castsi128_ps(_mm_set1_epi32(-1));
  alignas(16) float rows[3][4][kPlacementLanes];
  for (int i = 0; i < 3; ++i) {
    __m256d t = _mm256_setzero_pd();
    for (int k = 0; k < 3; ++k) t = sub(t, mul(inv[i][k], _mm256_cvtps_pd(lanes[k][3])));
    for (int j = 0; j < 4; ++j) {
      const __m128 value = _mm256_cvtpd_ps(j < 3 ? inv[i][j] : t);
      finite = _mm_and_ps(finite, finite_lanes(value));
      _mm_store_ps(rows[i][j], value);
    }
  }
  for (unsigned k = 0; k < count; ++k)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) out[k].m[i][j] = rows[i][j][k];
  const unsigned exists =
      static_cast<unsigned>(_mm256_movemask_pd(regular)) & static_cast<unsigned>(_mm_movemask_ps(finite));
  return exists & ((1u << count) - 1u);
}

}  // namespace rtpro
