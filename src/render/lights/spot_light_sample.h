#pragma once
// A spot light's side of shading (its scene side is scene/spot_light.h), inline as a point
// light's (render/lights/point_light_sample.h says why).
#include "rtpro/core/ray.h"
#include "light_sample_value.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/spot_light.h"

namespace rtpro {

inline int samples_per_axis(const SpotLight&) { return 1; }

// A point light times its cone's falloff: no distance falloff here either (as a point light's),
// and nothing arrives outside the outer cone.
inline LightSample sample_light_of_kind(const SpotLight& light, const Vec3& point, Sample2D) {
  const Vec3 to_light = light.position - point;
  const float distance = length(to_light);
  const Vec3 direction = to_light / distance;
  return {direction, distance, light.radiance * light.falloff(-direction)};
}

inline float hit_light_of_kind(const SpotLight&, const Ray&, float) { return kLightMissed; }
inline Color emission_of_kind(const SpotLight&) { return Color(0.0f); }

}  // namespace rtpro
