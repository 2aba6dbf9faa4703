#pragma once
// What shading needs from a light at a point: where it is and what arrives, one shadow ray's
// worth at a time. Point, spot and directional lights need one sample; an area light needs
// samples_per_axis² stratified ones, whose radiances average to what the whole light delivers.
// Each light kind in the Light variant adds one sample_light_of_kind overload (below) and one
// overload of each function in light_sample.cpp; shading never names a kind.
#include "rtpro/core/ray.h"
#include "rtpro/core/vec3.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/light.h"

#include <limits>
#include <optional>
#include <variant>

namespace rtpro {

struct LightSample {
  Vec3 direction;  // unit, from the point towards the light
  float distance;  // to the light; infinity for directional lights
  // Arriving at the point along `direction`, as the estimate of the whole light from this one
  // sample (1 / pdf in solid angle folded in); zero when nothing arrives (behind a one-sided
  // light, inside a sphere light). Average over the light's samples.
  Color radiance;
};

// The side of the stratified grid of shadow samples: 1 for point, spot and directional lights.
int light_samples_per_axis(const Light& light);

// One overload per light kind; `u` picks the sample (area lights: a point of [0,1)²; ignored by
// point, spot and directional lights, whose overloads are inline: every shading point of a Whitted
// scene calls them, and out of line the call and the variant's dispatch cost more than the arithmetic).
inline LightSample sample_light_of_kind(const PointLight& light, const Vec3& point, Sample2D) {
  const Vec3 to_light = light.position - point;
  const float distance = length(to_light);
  return {to_light / distance, distance, light.radiance};
}
// A point light times its cone's falloff: no distance falloff here either (the Whitted model), and
// nothing arrives outside the outer cone.
inline LightSample sample_light_of_kind(const SpotLight& light, const Vec3& point, Sample2D) {
  const Vec3 to_light = light.position - point;
  const float distance = length(to_light);
  const Vec3 direction = to_light / distance;
  return {direction, distance, light.radiance * light.falloff(-direction)};
}
inline LightSample sample_light_of_kind(const DirectionalLight& light, const Vec3&, Sample2D) {
  return {light.to_light, std::numeric_limits<float>::infinity(), light.radiance};
}
LightSample sample_light_of_kind(const SphereLight& light, const Vec3& point, Sample2D u);
LightSample sample_light_of_kind(const QuadLight& light, const Vec3& point, Sample2D u);

inline LightSample sample_light(const Light& light, const Vec3& point, Sample2D u) {
  return std::visit([&](const auto& l) { return sample_light_of_kind(l, point, u); }, light);
}

// An area light's emitting surface as seen by a camera or mirror ray: the ray parameter of the
// nearest visible hit in (ray.tnear, t_max), or nothing (always for point, spot and directional
// lights, which are never seen). What it shows is light_emission().
std::optional<float> hit_light(const Light& light, const Ray& ray, float t_max);
Color light_emission(const Light& light);

}  // namespace rtpro
