#pragma once
// The one place secondary rays are spawned. The origin is pushed off the surface along the
// geometric normal by the point's error bound and rounded away from it (pbrt's approach), so a
// spawned ray never re-hits the surface it leaves.
//
// Inline: these run once per shadow and reflection ray, and out of line the caller reloaded each
// returned ray as one 16-byte load over the callee's 4-byte stores, a store-forwarding stall that
// measured at about a tenth of the shading loop.
#include "rtpro/core/ray.h"
#include "surface.h"

#include <emmintrin.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rtpro {

namespace ray_offset_detail {

// The next float towards +inf or -inf (pbrt's NextFloatUp/Down); std::nextafter is a libm call
// that showed up at 4.5% of a render's instructions. Inputs are finite surface coordinates.
//
// Tracing threads run with flush-to-zero and denormals-are-zero (core/fp_env.h), where every
// denormal counts as zero: a step onto a denormal would leave the origin on a surface at 0. So
// the step skips the denormals: from zero (or a denormal) it goes to the smallest normal float,
// and a step down to a denormal lands on zero.
inline float next_float(float v, bool up) {
  constexpr float kSmallestNormal = std::numeric_limits<float>::min();
  if (std::fabs(v) < kSmallestNormal) return up ? kSmallestNormal : -kSmallestNormal;
  std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
  if ((v > 0.0f) == up) ++bits;
  else --bits;
  const float next = std::bit_cast<float>(bits);
  return std::fabs(next) < kSmallestNormal ? 0.0f : next;
}

}  // namespace ray_offset_detail

// offset_ray_origin one coordinate at a time: the definition the SSE version below computes in
// one go (tests compare the two).
inline Vec3 offset_ray_origin_per_axis(const SurfacePoint& surface, const Vec3& direction) {
  const bool leaving_front = dot(direction, surface.geometric_normal) >= 0.0f;
  const Vec3 n = leaving_front ? surface.geometric_normal : -surface.geometric_normal;
  const float distance = dot(abs(n), Vec3(surface.position_error));
  Vec3 origin = surface.position + n * distance;
  // Round each coordinate away from the surface so the float sum cannot land back on it. The
  // side comes from the normal, not from the offset: an error bound below the smallest normal
  // float makes the offset exactly zero under flush-to-zero, and the step must happen anyway.
  for (int axis = 0; axis < 3; ++axis) {
    if (n[axis] != 0.0f) origin[axis] = ray_offset_detail::next_float(origin[axis], n[axis] > 0.0f);
  }
  return origin;
}

// next_float lane by lane where `n` (a normal coordinate) is non-zero, towards n's sign; lanes where
// n is zero keep `origin`. The rounding step of offset_ray_origin, with masks instead of branches:
// per coordinate it branched four ways, and the branches cost more than the arithmetic.
inline __m128 round_away_from_surface(__m128 origin, __m128 n) {
  const __m128 sign_bit = _mm_set1_ps(-0.0f);
  const __m128 smallest_normal = _mm_set1_ps(std::numeric_limits<float>::min());
  const __m128 zero = _mm_setzero_ps();
  const __m128 up = _mm_cmpgt_ps(n, zero);
  // One ulp up or down in magnitude by the integer bits ...
  const __m128 step_down = _mm_xor_ps(_mm_cmpgt_ps(origin, zero), up);  // towards zero: all ones, i.e. −1
  const __m128i step = _mm_or_si128(_mm_castps_si128(_mm_andnot_ps(step_down, _mm_castsi128_ps(_mm_set1_epi32(1)))),
                                    _mm_castps_si128(step_down));
  __m128 next = _mm_castsi128_ps(_mm_add_epi32(_mm_castps_si128(origin), step));
  next = _mm_andnot_ps(_mm_cmplt_ps(_mm_andnot_ps(sign_bit, next), smallest_normal), next);  // a denormal is 0
  // ... except from zero or a denormal, which goes to the smallest normal float on the normal's side.
  const __m128 from_zero =
      _mm_or_ps(_mm_and_ps(up, smallest_normal), _mm_andnot_ps(up, _mm_xor_ps(smallest_normal, sign_bit)));
  const __m128 tiny = _mm_cmplt_ps(_mm_andnot_ps(sign_bit, origin), smallest_normal);
  const __m128 stepped = _mm_or_ps(_mm_and_ps(tiny, from_zero), _mm_andnot_ps(tiny, next));
  const __m128 moves = _mm_cmpneq_ps(n, zero);
  return _mm_or_ps(_mm_and_ps(moves, stepped), _mm_andnot_ps(moves, origin));
}

// The origin of a ray leaving the surface on the front (the geometric normal's side) or the back:
// offset_ray_origin_per_axis, bit for bit, with the three coordinates in one SSE2 register (about
// 55 instructions a spawned ray with the branches, 7% of a render's). Lane 3 is never stored.
inline Vec3 offset_ray_origin_on_side(const SurfacePoint& surface, bool leaving_front) {
  const Vec3& g = surface.geometric_normal;
  const float distance = dot(abs(g), Vec3(surface.position_error));  // |−g| is |g|
  const __m128 n = _mm_xor_ps(_mm_set_ps(0.0f, g.z, g.y, g.x), leaving_front ? _mm_setzero_ps() : _mm_set1_ps(-0.0f));
  const __m128 p = _mm_set_ps(0.0f, surface.position.z, surface.position.y, surface.position.x);
  const __m128 origin = _mm_add_ps(p, _mm_mul_ps(n, _mm_set1_ps(distance)));
  alignas(16) float out[4];
  _mm_store_ps(out, round_away_from_surface(origin, n));
  return {out[0], out[1], out[2]};
}

inline bool leaves_front(const SurfacePoint& surface, const Vec3& direction) {
  return dot(direction, surface.geometric_normal) >= 0.0f;
}

inline Vec3 offset_ray_origin(const SurfacePoint& surface, const Vec3& direction) {
  return offset_ray_origin_on_side(surface, leaves_front(surface, direction));
}

// A surface point's offset origins, each side's computed on first use: a path vertex's shadow ray
// and next ray mostly leave on the same side, and the offset is 30-odd instructions a ray. The
// origins are offset_ray_origin's, bit for bit.
class SpawnOrigins {
 public:
  explicit SpawnOrigins(const SurfacePoint& surface) : surface_(surface) {}

  Vec3 towards(const Vec3& direction) {
    const bool front = leaves_front(surface_, direction);
    if (!known_[front]) {
      origins_[front] = offset_ray_origin_on_side(surface_, front);
      known_[front] = true;
    }
    return origins_[front];
  }
  const SurfacePoint& surface() const { return surface_; }

 private:
  const SurfacePoint& surface_;
  Vec3 origins_[2];
  bool known_[2] = {false, false};
};

// A ray leaving the surface in `direction`.
inline Ray spawn_ray(const SurfacePoint& surface, const Vec3& direction) {
  Ray ray;
  ray.org = offset_ray_origin(surface, direction);
  ray.dir = direction;
  return ray;
}

inline Ray spawn_ray(SpawnOrigins& origins, const Vec3& direction) {
  Ray ray;
  ray.org = origins.towards(direction);
  ray.dir = direction;
  return ray;
}

// A ray from the surface to `target`; it spans t in (0, 1) so `target` itself is excluded.
inline Ray spawn_ray_to(const SurfacePoint& surface, const Vec3& target) {
  Ray ray;
  ray.org = offset_ray_origin(surface, target - surface.position);
  ray.dir = target - ray.org;
  // Stop just short of the target so a light placed on a surface is not shadowed by it.
  ray.tfar = 1.0f - 0x1p-16f;
  return ray;
}

inline Ray spawn_ray_to(SpawnOrigins& origins, const Vec3& target) {
  Ray ray;
  ray.org = origins.towards(target - origins.surface().position);
  ray.dir = target - ray.org;
  ray.tfar = 1.0f - 0x1p-16f;
  return ray;
}

}  // namespace rtpro
