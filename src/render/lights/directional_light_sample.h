#pragma once
// A directional light's side of shading (its scene side is scene/directional_light.h), inline as
// a point light's (render/lights/point_light_sample.h says why).
#include "rtpro/core/ray.h"
#include "light_sample_value.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/directional_light.h"

#include <limits>

namespace rtpro {

inline int samples_per_axis(const DirectionalLight&) { return 1; }

inline LightSample sample_light_of_kind(const DirectionalLight& light, const Vec3&, Sample2D) {
  return {light.to_light, std::numeric_limits<float>::infinity(), light.radiance};
}

inline float hit_light_of_kind(const DirectionalLight&, const Ray&, float) { return kLightMissed; }
inline Color emission_of_kind(const DirectionalLight&) { return Color(0.0f); }

}  // namespace rtpro
