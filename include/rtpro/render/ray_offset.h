#pragma once
// The one place secondary rays are spawned. The origin is pushed off the surface along the
// geometric normal by the point's error bound and rounded away from it (pbrt's approach), so a
// spawned ray never re-hits the surface it leaves.
//
// Inline: these run once per shadow and reflection ray, and out of line the caller reloaded each
// returned ray as one 16-byte load over the callee's 4-byte stores, a store-forwarding stall that
// measured at about a tenth of the shading loop.
#include "rtpro/core/ray.h"
#include "rtpro/render/surface.h"

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

inline Vec3 offset_ray_origin(const SurfacePoint& surface, const Vec3& direction) {
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

// A ray leaving the surface in `direction`.
inline Ray spawn_ray(const SurfacePoint& surface, const Vec3& direction) {
  Ray ray;
  ray.org = offset_ray_origin(surface, direction);
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

}  // namespace rtpro
