#include "light_linking.h"

#include <cmath>
#include <limits>

namespace rtpro {

namespace {

// The first hit along `ray` (before its end, as an occlusion query sees it) on an object that
// casts the shadows of `light`. Each step starts just past the last hit, so t only grows.
bool blocked_by_a_shadow_caster(const Backend& backend, const LightLinks& links, Ray ray, float time,
                                std::uint32_t light) {
  const float end = ray.tfar;
  Hit hit;
  while (backend.intersect(ray, time, hit) && hit.t < end) {
    if (links.casts_shadow(link_group_of(links, hit), light)) return true;
    ray.tnear = std::nextafter(hit.t, std::numeric_limits<float>::infinity());
    if (!(ray.tnear < end)) return false;
  }
  return false;
}

}  // namespace

void occluded_with_shadow_linking(const Backend& backend, const LightLinks& links, std::span<const Ray> rays,
                                  std::span<const float> times, std::span<const std::uint32_t> light_of_ray,
                                  std::span<std::uint8_t> occluded, RayCoherence coherence) {
  backend.occluded(rays, times, occluded, coherence);
  if (!links.linked()) return;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const std::uint32_t light = light_of_ray[i];
    if (occluded[i] && light != kInvalidId && links.shadow_linked(light))
      occluded[i] = blocked_by_a_shadow_caster(backend, links, rays[i], times.empty() ? 0.0f : times[i], light) ? 1 : 0;
  }
}

}  // namespace rtpro
