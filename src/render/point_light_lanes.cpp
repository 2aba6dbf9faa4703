#include "point_light_lanes.h"

#include "lanes3.h"
#include "rtpro/core/avx2_clones.h"
#include "rtpro/render/ray_offset.h"

#include <emmintrin.h>

#include <limits>

namespace rtpro {

using lanes::dot;
using lanes::gather;
using lanes::Lanes3;

namespace {

// One light's lanes for surfaces already in lanes.
[[gnu::always_inline]] inline void one_light(const PointLight& light, const Lanes3& p, const Lanes3& ns,
                                             const Lanes3& ng, const Lanes3& mirror, __m128 error,
                                             PointLightLanes& out) {
  // sample_light: to_light = position − point, distance = |to_light|, direction = to_light / distance.
  const Lanes3 to_light{_mm_sub_ps(_mm_set1_ps(light.position.x), p.x), _mm_sub_ps(_mm_set1_ps(light.position.y), p.y),
                        _mm_sub_ps(_mm_set1_ps(light.position.z), p.z)};
  const __m128 distance = _mm_sqrt_ps(dot(to_light, to_light));
  const Lanes3 direction{_mm_div_ps(to_light.x, distance), _mm_div_ps(to_light.y, distance),
                         _mm_div_ps(to_light.z, distance)};
  const __m128 n_dot_l = dot(ns, direction);
  const __m128 g_dot_l = dot(ng, direction);
  const __m128 r_dot_l = dot(mirror, direction);

  // spawn_ray_to(surface, point + direction·distance): the origin pushed off along the geometric
  // normal on the side of the target, then rounded away from the surface.
  const Lanes3 target{_mm_add_ps(p.x, _mm_mul_ps(direction.x, distance)),
                      _mm_add_ps(p.y, _mm_mul_ps(direction.y, distance)),
                      _mm_add_ps(p.z, _mm_mul_ps(direction.z, distance))};
  const Lanes3 towards{_mm_sub_ps(target.x, p.x), _mm_sub_ps(target.y, p.y), _mm_sub_ps(target.z, p.z)};
  const __m128 sign_bit = _mm_set1_ps(-0.0f);
  const __m128 behind = _mm_andnot_ps(_mm_cmpge_ps(dot(towards, ng), _mm_setzero_ps()), sign_bit);
  const Lanes3 n{_mm_xor_ps(ng.x, behind), _mm_xor_ps(ng.y, behind), _mm_xor_ps(ng.z, behind)};
  // dot(|n|, (e, e, e)); |−g| is |g|.
  const __m128 offset = _mm_add_ps(
      _mm_add_ps(_mm_mul_ps(_mm_andnot_ps(sign_bit, ng.x), error), _mm_mul_ps(_mm_andnot_ps(sign_bit, ng.y), error)),
      _mm_mul_ps(_mm_andnot_ps(sign_bit, ng.z), error));
  const Lanes3 origin{round_away_from_surface(_mm_add_ps(p.x, _mm_mul_ps(n.x, offset)), n.x),
                      round_away_from_surface(_mm_add_ps(p.y, _mm_mul_ps(n.y, offset)), n.y),
                      round_away_from_surface(_mm_add_ps(p.z, _mm_mul_ps(n.z, offset)), n.z)};
  const Lanes3 ray_direction{_mm_sub_ps(target.x, origin.x), _mm_sub_ps(target.y, origin.y),
                             _mm_sub_ps(target.z, origin.z)};

  float ox[4], oy[4], oz[4], dx[4], dy[4], dz[4];
  lanes::store(origin, ox, oy, oz);
  lanes::store(ray_direction, dx, dy, dz);
  _mm_storeu_ps(out.n_dot_l, n_dot_l);
  _mm_storeu_ps(out.r_dot_l, r_dot_l);
  for (int i = 0; i < 4; ++i) {
    Ray& ray = out.rays[i];
    ray.org.x = ox[i];
    ray.org.y = oy[i];
    ray.org.z = oz[i];
    ray.tnear = 0.0f;
    ray.dir.x = dx[i];
    ray.dir.y = dy[i];
    ray.dir.z = dz[i];
    ray.tfar = 1.0f - 0x1p-16f;
  }
  const __m128 zero = _mm_setzero_ps();
  out.lit = static_cast<std::uint32_t>(
      _mm_movemask_ps(_mm_and_ps(_mm_cmpnle_ps(n_dot_l, zero), _mm_cmpnle_ps(g_dot_l, zero))));
  out.infinite = static_cast<std::uint32_t>(_mm_movemask_ps(
      _mm_cmpeq_ps(_mm_andnot_ps(sign_bit, distance), _mm_set1_ps(std::numeric_limits<float>::infinity()))));
}

}  // namespace

RTPRO_AVX2_CLONES
void point_light_lanes(std::span<const PointLight* const> lights, const SurfacePoint* const surfaces[4],
                       const Vec3* const mirrors[4], PointLightLanes* out) {
  const Lanes3 p = gather([&](int i) { return surfaces[i]->position; });
  const Lanes3 ns = gather([&](int i) { return surfaces[i]->shading_normal; });
  const Lanes3 ng = gather([&](int i) { return surfaces[i]->geometric_normal; });
  const Lanes3 mirror = gather([&](int i) { return *mirrors[i]; });
  const __m128 error = _mm_setr_ps(surfaces[0]->position_error, surfaces[1]->position_error,
                                   surfaces[2]->position_error, surfaces[3]->position_error);

  for (std::size_t l = 0; l < lights.size(); ++l)
    if (lights[l]) one_light(*lights[l], p, ns, ng, mirror, error, out[l]);
}

}  // namespace rtpro
