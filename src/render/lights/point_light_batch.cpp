#include "point_light_batch.h"

#include "rtpro/core/lanes3.h"
#include "rtpro/core/avx2_clones.h"

#include <emmintrin.h>

namespace rtpro {

RTPRO_AVX2_CLONES
void sample_point_light_batch(const PointLight& light, std::span<const SurfacePoint> points,
                              std::span<PathLightSample> out, std::span<std::uint8_t> found) {
  using lanes::dot;
  using lanes::Lanes3;
  std::size_t i = 0;
  for (; i + 4 <= points.size(); i += 4) {
    const Lanes3 p = lanes::gather([&](int k) { return points[i + k].position; });
    const Lanes3 to_light{_mm_sub_ps(_mm_set1_ps(light.position.x), p.x),
                          _mm_sub_ps(_mm_set1_ps(light.position.y), p.y),
                          _mm_sub_ps(_mm_set1_ps(light.position.z), p.z)};
    const __m128 d2 = dot(to_light, to_light);
    const __m128 d = _mm_sqrt_ps(d2);
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 inverse_d = _mm_div_ps(one, d);
    const __m128 inverse_d2 = light.inverse_square ? _mm_div_ps(one, d2) : one;
    alignas(16) float dx[4], dy[4], dz[4], rx[4], ry[4], rz[4], distance[4];
    lanes::store(
        {_mm_mul_ps(to_light.x, inverse_d), _mm_mul_ps(to_light.y, inverse_d), _mm_mul_ps(to_light.z, inverse_d)}, dx,
        dy, dz);
    lanes::store(
        {_mm_mul_ps(_mm_set1_ps(light.radiance.x), inverse_d2), _mm_mul_ps(_mm_set1_ps(light.radiance.y), inverse_d2),
         _mm_mul_ps(_mm_set1_ps(light.radiance.z), inverse_d2)},
        rx, ry, rz);
    _mm_store_ps(distance, d);
    // !(d2 > 0), as the scalar test: a point at the light, or NaN.
    const int lit = _mm_movemask_ps(_mm_cmpgt_ps(d2, _mm_setzero_ps()));
    for (int k = 0; k < 4; ++k) {
      PathLightSample& s = out[i + k];
      s.direction = {dx[k], dy[k], dz[k]};
      s.distance = distance[k];
      s.radiance = {rx[k], ry[k], rz[k]};
      s.pdf = 1.0f;
      s.delta = true;
      s.environment = nullptr;
      found[i + k] = (lit >> k) & 1;
    }
  }
  for (; i < points.size(); ++i) found[i] = sample_point_light(light, points[i].position, out[i]);
}

}  // namespace rtpro
