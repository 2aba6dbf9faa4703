#include "point_light_lanes.h"

#include "rtpro/core/lanes3.h"
#include "rtpro/core/avx2_clones.h"
#include "ray_offset.h"

#include <emmintrin.h>

#include <cstddef>
#include <limits>

namespace rtpro {

using lanes::dot;
using lanes::gather;
using lanes::Lanes3;
using lanes::Lanes4;
using lanes::select;
using lanes::transpose_rows;

namespace {

// offset_ray_origin_on_side for four surfaces: the origin pushed off by `offset` along `n` (the
// geometric normal, or its negation for the back), then rounded away from the surface.
[[gnu::always_inline]] inline Lanes3 offset_origins(const Lanes3& p, const Lanes3& n, __m128 offset) {
  return {round_away_from_surface(_mm_add_ps(p.x, _mm_mul_ps(n.x, offset)), n.x),
          round_away_from_surface(_mm_add_ps(p.y, _mm_mul_ps(n.y, offset)), n.y),
          round_away_from_surface(_mm_add_ps(p.z, _mm_mul_ps(n.z, offset)), n.z)};
}

// The four surfaces in lanes, and their origins on each side: the front one made up front, the
// back one when a shadow ray first needs it (rarely: a light the geometric normal faces is on its
// side but for rounding).
struct SurfaceLanes {
  Lanes3 p, ns, ng, mirror;
  __m128 offset;
  Lanes3 front;
  Lanes3 back;
  bool back_known = false;
};

// One light's lanes for the four surfaces.
[[gnu::always_inline]] inline void one_light(const PointLight& light, SurfaceLanes& s, PointLightLanes& out) {
  const Lanes3& p = s.p;
  const Lanes3& ng = s.ng;
  const __m128 zero = _mm_setzero_ps();
  const __m128 sign_bit = _mm_set1_ps(-0.0f);
  // sample_light: to_light = position − point, distance = |to_light|, direction = to_light / distance.
  const Lanes3 to_light{_mm_sub_ps(_mm_set1_ps(light.position.x), p.x), _mm_sub_ps(_mm_set1_ps(light.position.y), p.y),
                        _mm_sub_ps(_mm_set1_ps(light.position.z), p.z)};
  const __m128 distance = _mm_sqrt_ps(dot(to_light, to_light));
  const Lanes3 direction{_mm_div_ps(to_light.x, distance), _mm_div_ps(to_light.y, distance),
                         _mm_div_ps(to_light.z, distance)};
  const __m128 n_dot_l = dot(s.ns, direction);
  const __m128 g_dot_l = dot(ng, direction);
  const __m128 r_dot_l = dot(s.mirror, direction);
  out.lit = static_cast<std::uint32_t>(
      _mm_movemask_ps(_mm_and_ps(_mm_cmpnle_ps(n_dot_l, zero), _mm_cmpnle_ps(g_dot_l, zero))));
  out.infinite = static_cast<std::uint32_t>(_mm_movemask_ps(
      _mm_cmpeq_ps(_mm_andnot_ps(sign_bit, distance), _mm_set1_ps(std::numeric_limits<float>::infinity()))));

  // spawn_ray_to(surface, point + direction·distance): the origin on the side of the target.
  const Lanes3 target{_mm_add_ps(p.x, _mm_mul_ps(direction.x, distance)),
                      _mm_add_ps(p.y, _mm_mul_ps(direction.y, distance)),
                      _mm_add_ps(p.z, _mm_mul_ps(direction.z, distance))};
  const Lanes3 towards{_mm_sub_ps(target.x, p.x), _mm_sub_ps(target.y, p.y), _mm_sub_ps(target.z, p.z)};
  const __m128 behind = _mm_cmpnge_ps(dot(towards, ng), zero);  // !(dot >= 0), NaN included
  Lanes3 origin = s.front;
  if (_mm_movemask_ps(behind) & out.lit & ~out.infinite) {
    if (!s.back_known) {
      s.back = offset_origins(p, {_mm_xor_ps(ng.x, sign_bit), _mm_xor_ps(ng.y, sign_bit), _mm_xor_ps(ng.z, sign_bit)},
                              s.offset);
      s.back_known = true;
    }
    origin = select(behind, s.back, s.front);
  }
  const Lanes3 ray_direction{_mm_sub_ps(target.x, origin.x), _mm_sub_ps(target.y, origin.y),
                             _mm_sub_ps(target.z, origin.z)};

  // The lanes turned into rays: 16-byte rows of origin and tnear, and of direction and tfar.
  __m128 ox = origin.x, oy = origin.y, oz = origin.z, tnear = _mm_setzero_ps();
  _MM_TRANSPOSE4_PS(ox, oy, oz, tnear);
  out.origin_rows[0] = ox;
  out.origin_rows[1] = oy;
  out.origin_rows[2] = oz;
  out.origin_rows[3] = tnear;
  __m128 dx = ray_direction.x, dy = ray_direction.y, dz = ray_direction.z, tfar = _mm_set1_ps(1.0f - 0x1p-16f);
  _MM_TRANSPOSE4_PS(dx, dy, dz, tfar);
  out.direction_rows[0] = dx;
  out.direction_rows[1] = dy;
  out.direction_rows[2] = dz;
  out.direction_rows[3] = tfar;
  _mm_storeu_ps(out.n_dot_l, n_dot_l);
  _mm_storeu_ps(out.r_dot_l, r_dot_l);
}

}  // namespace

RTPRO_AVX2_CLONES
void point_light_lanes(std::span<const PointLight* const> lights, const SurfacePoint* const surfaces[4],
                       const Vec3* const mirrors[4], PointLightLanes* out, Vec3 front_origins[4]) {
  SurfaceLanes s;
  // Rows of 16 bytes, within the record: the shading normal's is followed by the position error;
  // the other fourth floats are not read.
  static_assert(offsetof(SurfacePoint, position_error) == offsetof(SurfacePoint, shading_normal) + 12);
  const auto rows = [&](auto field) {
    return transpose_rows(&(surfaces[0]->*field).x, &(surfaces[1]->*field).x, &(surfaces[2]->*field).x,
                          &(surfaces[3]->*field).x);
  };
  s.p = rows(&SurfacePoint::position).xyz;
  s.ng = rows(&SurfacePoint::geometric_normal).xyz;
  const Lanes4 shading = rows(&SurfacePoint::shading_normal);
  s.ns = shading.xyz;
  const __m128 error = shading.w;
  s.mirror = gather([&](int i) { return *mirrors[i]; });  // a bare Vec3: no fourth float to read
  // dot(|g|, (e, e, e)); |−g| is |g|.
  const __m128 sign_bit = _mm_set1_ps(-0.0f);
  s.offset = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_andnot_ps(sign_bit, s.ng.x), error),
                                   _mm_mul_ps(_mm_andnot_ps(sign_bit, s.ng.y), error)),
                        _mm_mul_ps(_mm_andnot_ps(sign_bit, s.ng.z), error));
  s.front = offset_origins(s.p, s.ng, s.offset);
  float fx[4], fy[4], fz[4];
  lanes::store(s.front, fx, fy, fz);
  for (int i = 0; i < 4; ++i) front_origins[i] = Vec3(fx[i], fy[i], fz[i]);
  for (std::size_t l = 0; l < lights.size(); ++l)
    if (lights[l]) one_light(*lights[l], s, out[l]);
}

}  // namespace rtpro
