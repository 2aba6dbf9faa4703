#include "medium_shadows.h"

#include "light_linking.h"
#include "medium_tracking.h"
#include "surface.h"

#include <cmath>
#include <limits>

namespace rtpro {

namespace {

constexpr float kShadowInfinity = std::numeric_limits<float>::infinity();
// As for the path's own rays (path_medium_step.cpp): a bound on a ray's cost.
constexpr int kMaxShadowCrossings = 256;

// Whether the hit's object lets the ray through without being crossed: it casts no shadows of
// `light` (light linking).
bool passes_linked(const LightLinks& links, const Hit& hit, std::uint32_t light) {
  return links.linked() && light != kInvalidId && !links.casts_shadow(link_group_of(links, hit), light);
}

// `time`: the ray's under an open shutter, else NaN (the shapes at the frame's time).
Color walk(const Backend& backend, const RenderScene& scene, Ray ray, float time,
           const PathWorkspace::MediumShadow& start) {
  const bool timed = !std::isnan(time);
  TrackingRandom random(start.seed);
  MediumStack media = start.media;
  Color transmitted(1.0f);
  const float end = ray.tfar;
  const float scale = length(ray.dir);
  for (int crossings = 0;; ++crossings) {
    Hit hit;
    const bool found = (timed ? backend.intersect(ray, time, hit) : backend.intersect(ray, hit)) && hit.t < end;
    const std::uint32_t medium = media.current(scene.world_medium);
    if (medium != kNoMedium) {
      const Ray unit{ray.org, ray.tnear * scale, ray.dir * (1.0f / scale), kShadowInfinity};
      transmitted = transmitted * transmittance(scene.media[medium], unit, (found ? hit.t : end) * scale, random);
      if (!(max_component(transmitted) > 0.0f)) return Color(0.0f);
    }
    if (!found) return transmitted;
    if (crossings == kMaxShadowCrossings) return Color(0.0f);
    if (!passes_linked(scene.links, hit, start.light)) {
      SurfacePoint surface;
      if (timed) make_surface_at(scene, ray, time, hit, surface);
      else make_surface(scene, ray, hit, surface);
      const Material& material = scene.materials[surface.material];
      if (!material.index_matched) return Color(0.0f);
      media.cross(*material.interior, surface.front_face);
    }
    ray.tnear = std::nextafter(hit.t, kShadowInfinity);
    if (!(ray.tnear < end)) return transmitted;
  }
}

}  // namespace

void medium_shadow_transmittance(const Backend& backend, const RenderScene& scene, std::span<const Ray> rays,
                                 std::span<const float> times, std::span<const PathWorkspace::MediumShadow> starts,
                                 std::span<Color> transmitted) {
  const float untimed = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < rays.size(); ++i)
    transmitted[i] = walk(backend, scene, rays[i], times.empty() ? untimed : times[i], starts[i]);
}

}  // namespace rtpro
