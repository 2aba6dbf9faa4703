#include "sphere_lanes.h"

#include "rtpro/geometry/sphere_intersect.h"

#include <immintrin.h>

namespace rtpro {

namespace {

std::uint32_t scalar_lanes(const Vec3& center, float radius, const RayLanes& rays, std::uint32_t active, float* t_hit) {
  std::uint32_t hits = 0;
  for (unsigned i = 0; i < rays.count; ++i) {
    if (!(active >> i & 1u)) continue;
    float t;
    if (intersect_sphere(center, radius, {rays.org_x[i], rays.org_y[i], rays.org_z[i]},
                         {rays.dir_x[i], rays.dir_y[i], rays.dir_z[i]}, rays.tnear[i], rays.tfar[i], t)) {
      t_hit[i] = t;
      hits |= 1u << i;
    }
  }
  return hits;
}

// Four lanes from `first`, each step the scalar function's (sphere_intersect.h), with its early
// returns turned into masks. NaNs go where the scalar code sends them: a NaN discriminant passes
// its `disc < 0` test there too and then fails every range comparison.
[[gnu::target("avx2")]] std::uint32_t four_lanes(const Vec3& center, float radius, const RayLanes& rays,
                                                 std::uint32_t active, unsigned first, float* t_hit) {
  const __m256d fx = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(rays.org_x + first)), _mm256_set1_pd(center.x));
  const __m256d fy = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(rays.org_y + first)), _mm256_set1_pd(center.y));
  const __m256d fz = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(rays.org_z + first)), _mm256_set1_pd(center.z));
  const __m256d dx = _mm256_cvtps_pd(_mm_loadu_ps(rays.dir_x + first));
  const __m256d dy = _mm256_cvtps_pd(_mm_loadu_ps(rays.dir_y + first));
  const __m256d dz = _mm256_cvtps_pd(_mm_loadu_ps(rays.dir_z + first));
  const __m128 tnear = _mm_loadu_ps(rays.tnear + first);
  const __m128 tfar = _mm_loadu_ps(rays.tfar + first);
  const __m256d zero = _mm256_setzero_pd();

  const __m256d a = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
  const __m256d b = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(fx, dx), _mm256_mul_pd(fy, dy)), _mm256_mul_pd(fz, dz));
  const __m256d r = _mm256_set1_pd(radius);
  const __m256d r2 = _mm256_mul_pd(r, r);
  const __m256d c = _mm256_sub_pd(
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(fx, fx), _mm256_mul_pd(fy, fy)), _mm256_mul_pd(fz, fz)), r2);
  // Lanes the scalar function gives up on early: a <= 0 (or NaN), or the origin outside and moving
  // away (c > 0 && b > 0 && tnear >= 0).
  const int positive_a = _mm256_movemask_pd(_mm256_cmp_pd(a, zero, _CMP_GT_OQ));
  const int leaving =
      _mm256_movemask_pd(_mm256_and_pd(_mm256_cmp_pd(c, zero, _CMP_GT_OQ), _mm256_cmp_pd(b, zero, _CMP_GT_OQ))) &
      _mm_movemask_ps(_mm_cmpge_ps(tnear, _mm_setzero_ps()));
  // The common miss (a shadow ray leaving the surface it starts on) ends here, as in the scalar
  // function, before the divisions.
  int live = positive_a & ~leaving & static_cast<int>(active >> first & 0xFu);
  if (live == 0) return 0;
  const __m256d s = _mm256_div_pd(b, a);
  const __m256d lx = _mm256_sub_pd(fx, _mm256_mul_pd(s, dx));
  const __m256d ly = _mm256_sub_pd(fy, _mm256_mul_pd(s, dy));
  const __m256d lz = _mm256_sub_pd(fz, _mm256_mul_pd(s, dz));
  const __m256d l2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(lx, lx), _mm256_mul_pd(ly, ly)), _mm256_mul_pd(lz, lz));
  const __m256d disc = _mm256_mul_pd(a, _mm256_sub_pd(r2, l2));
  live &= ~_mm256_movemask_pd(_mm256_cmp_pd(disc, zero, _CMP_LT_OQ));
  if (live == 0) return 0;

  const __m256d sign_bit = _mm256_set1_pd(-0.0);
  const __m256d root = _mm256_sqrt_pd(disc);
  const __m256d signed_root = _mm256_or_pd(_mm256_andnot_pd(sign_bit, root), _mm256_and_pd(sign_bit, b));
  const __m256d q = _mm256_xor_pd(_mm256_add_pd(b, signed_root), sign_bit);
  const __m256d q_zero = _mm256_cmp_pd(q, zero, _CMP_EQ_OQ);
  __m256d t0 = _mm256_blendv_pd(_mm256_div_pd(q, a), zero, q_zero);
  __m256d t1 = _mm256_blendv_pd(_mm256_div_pd(c, q), zero, q_zero);
  const __m256d swap = _mm256_cmp_pd(t0, t1, _CMP_GT_OQ);
  const __m256d lower = _mm256_blendv_pd(t0, t1, swap);
  t1 = _mm256_blendv_pd(t1, t0, swap);
  t0 = lower;

  const __m128 near_root = _mm256_cvtpd_ps(t0);
  const __m128 far_root = _mm256_cvtpd_ps(t1);
  const __m128 near_ok = _mm_and_ps(_mm_cmpgt_ps(near_root, tnear), _mm_cmple_ps(near_root, tfar));
  const __m128 far_ok = _mm_and_ps(_mm_cmpgt_ps(far_root, tnear), _mm_cmple_ps(far_root, tfar));
  const __m128 t = _mm_blendv_ps(far_root, near_root, near_ok);
  const int hit_bits = live & _mm_movemask_ps(_mm_or_ps(near_ok, far_ok));
  alignas(16) float lanes[4];
  _mm_store_ps(lanes, t);
  for (int i = 0; i < 4; ++i)
    if (hit_bits >> i & 1) t_hit[first + static_cast<unsigned>(i)] = lanes[i];
  return static_cast<std::uint32_t>(hit_bits) << first;
}

[[gnu::target("avx2")]] std::uint32_t vector_lanes(const Vec3& center, float radius, const RayLanes& rays,
                                                   std::uint32_t active, float* t_hit) {
  std::uint32_t hits = 0;
  for (unsigned first = 0; first < rays.count; first += 4)
    if ((active >> first) & 0xFu) hits |= four_lanes(center, radius, rays, active, first, t_hit);
  return hits;
}

// __builtin_cpu_init first: the first call may come from a static initialiser, before the one of
// the runtime that fills in the CPU model.
bool cpu_has_avx2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
}

}  // namespace

// A function-local static, not a namespace-scope constant: other files' static initialisers ask
// too, and the order of initialisation across files is unspecified.
bool sphere_lanes_vectorised() {
  static const bool avx2 = cpu_has_avx2();
  return avx2;
}

std::uint32_t intersect_sphere_lanes(const Vec3& center, float radius, const RayLanes& rays, std::uint32_t active,
                                     float* t_hit) {
  if (sphere_lanes_vectorised() && rays.count % 4 == 0) return vector_lanes(center, radius, rays, active, t_hit);
  return scalar_lanes(center, radius, rays, active, t_hit);
}

}  // namespace rtpro
