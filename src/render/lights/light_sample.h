#pragma once
// What shading needs from a light at a point: where it is and what arrives, one shadow ray's
// worth at a time. Point, spot and directional lights need one sample; an area light needs
// samples_per_axis² stratified ones, whose radiances average to what the whole light delivers.
// Each light kind's side of shading is its own header, registered here by its include: its
// samples_per_axis, sample_light_of_kind, hit_light_of_kind and emission_of_kind, which the visits
// below name when a kind lacks one; shading never names a kind.
#include "rtpro/core/ray.h"
#include "rtpro/core/vec3.h"
#include "directional_light_sample.h"
#include "light_sample_value.h"
#include "point_light_sample.h"
#include "quad_light_sample.h"
#include "rtpro/render/sampler.h"
#include "sphere_light_sample.h"
#include "spot_light_sample.h"
#include "rtpro/scene/light.h"

#include <variant>

namespace rtpro {

// The side of the stratified grid of shadow samples: 1 for point, spot and directional lights.
int light_samples_per_axis(const Light& light);

// `u` picks the sample (area lights: a point of [0,1)²; ignored by point, spot and directional
// lights). Inline, as their overloads are (render/lights/point_light_sample.h says why).
inline LightSample sample_light(const Light& light, const Vec3& point, Sample2D u) {
  return std::visit([&](const auto& l) { return sample_light_of_kind(l, point, u); }, light);
}

// An area light's emitting surface as seen by a camera or mirror ray: the ray parameter of the
// nearest visible hit in (ray.tnear, t_max), or kLightMissed (always for point, spot and
// directional lights, which are never seen). What it shows is light_emission(). A float, not a
// std::optional: every camera and BSDF ray asks every sphere and quad light, and an optional<float>
// put together in memory field by field, then loaded whole, stalls on store forwarding.
float hit_light(const Light& light, const Ray& ray, float t_max);
Color light_emission(const Light& light);

}  // namespace rtpro
