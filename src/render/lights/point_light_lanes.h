#pragma once
// Point lights' shadow rays from four surfaces at once, in SSE2 registers: for every lane the
// answer of the scalar chain shading uses for a point light — sample_light (the direction and
// distance to the light), the three cosines, spawn_ray_to towards the light — bit for bit. IEEE
// add, subtract, multiply, divide and square root are exact per lane, the operations are the scalar
// ones in their order, and nothing is contracted, so a shadow ray does not depend on which
// surfaces shared its lanes. The scalar chain is a latency chain per surface and light (a square
// root, then divisions by it, then the offset); four lanes run one chain for four surfaces.
#include "rtpro/core/ray.h"
#include "surface.h"
#include "rtpro/scene/light.h"

#include <xmmintrin.h>

#include <cstddef>
#include <cstdint>
#include <span>

namespace rtpro {

struct PointLightLanes {
  // Lane i's ray, spawn_ray_to(surface, light position), for lanes lit with a finite distance: its
  // first 16 bytes (org, tnear) and its last (dir, tfar); store_ray writes it.
  __m128 origin_rows[4];
  __m128 direction_rows[4];
  float n_dot_l[4];  // shading normal · direction to the light
  float r_dot_l[4];  // mirror direction · direction to the light
  // Bit i: lane i needs its shadow ray (neither normal faces away from the light: the scalar test
  // `n_dot_l <= 0 || g_dot_l <= 0` is false, NaNs included).
  std::uint32_t lit = 0;
  // Bit i: the distance to the light overflowed to infinity; the lane's ray is not set (the scalar
  // chain spawns a ray along the direction instead).
  std::uint32_t infinite = 0;
};

// Lane k's ray into `out`, two 16-byte stores (Ray is org, tnear, dir, tfar, packed).
inline void store_ray(const PointLightLanes& lanes, unsigned k, Ray& out) {
  static_assert(sizeof(Ray) == 32 && offsetof(Ray, tnear) == 12 && offsetof(Ray, dir) == 16 &&
                offsetof(Ray, tfar) == 28);
  _mm_storeu_ps(&out.org.x, lanes.origin_rows[k]);
  _mm_storeu_ps(&out.dir.x, lanes.direction_rows[k]);
}

// surfaces[i] and mirrors[i] (unit mirror direction about surfaces[i]'s shading normal), i < 4;
// out[l] for each lights[l] that is not null. The surfaces are read once for all the lights, and
// their origins on the front, which the shadow rays mostly share, are made once:
// front_origins[i] is offset_ray_origin_on_side(*surfaces[i], true), bit for bit, for the mirror
// ray too.
void point_light_lanes(std::span<const PointLight* const> lights, const SurfacePoint* const surfaces[4],
                       const Vec3* const mirrors[4], PointLightLanes* out, Vec3 front_origins[4]);

}  // namespace rtpro
