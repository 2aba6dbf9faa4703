#pragma once
// A sphere light's side of shading (its scene side is scene/sphere_light.h): stratified samples
// of the cone it fills, and its surface as rays meet it.
#include "rtpro/core/ray.h"
#include "light_sample_value.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/sphere_light.h"

namespace rtpro {

inline int samples_per_axis(const SphereLight& light) { return light.samples_per_axis; }

// Uniform over the cone of directions the sphere fills; `u` is a point of [0,1)².
LightSample sample_light_of_kind(const SphereLight& light, const Vec3& point, Sample2D u);

// The ray parameter of the nearest visible hit on its surface in (ray.tnear, t_max), or
// kLightMissed.
float hit_light_of_kind(const SphereLight& light, const Ray& ray, float t_max);

inline Color emission_of_kind(const SphereLight& light) { return light.radiance; }

}  // namespace rtpro
