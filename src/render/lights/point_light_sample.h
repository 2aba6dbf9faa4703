#pragma once
// A point light's side of shading (its scene side is scene/point_light.h): one sample, one shadow
// ray, and nothing a ray can meet. Inline: every shading point of a Whitted scene calls these,
// and out of line the call and the variant's dispatch cost more than the arithmetic.
#include "rtpro/core/ray.h"
#include "light_sample_value.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/point_light.h"

namespace rtpro {

inline int samples_per_axis(const PointLight&) { return 1; }

// No distance falloff here: the light in whitted light units (scene/render_settings.h), which the
// whitted integrator converts a radiometric scene's lights into; `u` is not used.
inline LightSample sample_light_of_kind(const PointLight& light, const Vec3& point, Sample2D) {
  const Vec3 to_light = light.position - point;
  const float distance = length(to_light);
  return {to_light / distance, distance, light.radiance};
}

inline float hit_light_of_kind(const PointLight&, const Ray&, float) { return kLightMissed; }
inline Color emission_of_kind(const PointLight&) { return Color(0.0f); }

}  // namespace rtpro
