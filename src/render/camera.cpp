#include "rtpro/render/camera.h"

#include <cmath>
#include <numbers>

namespace rtpro {

Sample2D concentric_disk(Sample2D square) {
  const float u = 2.0f * square.x - 1.0f, v = 2.0f * square.y - 1.0f;
  if (u == 0.0f && v == 0.0f) return {0.0f, 0.0f};
  constexpr float kQuarterPi = std::numbers::pi_v<float> / 4.0f;
  const bool wide = std::fabs(u) > std::fabs(v);
  const float radius = wide ? u : v;
  const float angle = wide ? kQuarterPi * (v / u) : 2.0f * kQuarterPi - kQuarterPi * (u / v);
  return {radius * std::cos(angle), radius * std::sin(angle)};
}

Ray camera_ray(const RenderCamera& camera, float px, float py, Sample2D lens) {
  const float x = (2.0f * px * camera.inv_width - 1.0f) * camera.half_width;
  const float y = (1.0f - 2.0f * py * camera.inv_height) * camera.half_height;
  // The film point's direction at distance 1 along `forward`.
  const Vec3 through = camera.forward + camera.right * x + camera.true_up * y;
  Ray ray;
  if (camera.lens_radius == 0.0f) {
    ray.org = camera.position;
    ray.dir = normalize(through);
    return ray;
  }
  const Sample2D disk = concentric_disk(lens);
  const Vec3 on_lens = (camera.right * disk.x + camera.true_up * disk.y) * camera.lens_radius;
  const Vec3 in_focus = through * camera.focus_distance;  // relative to the lens centre
  ray.org = camera.position + on_lens;
  ray.dir = normalize(in_focus - on_lens);
  return ray;
}

}  // namespace rtpro
