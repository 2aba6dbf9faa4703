#pragma once
// A quad light's side of shading (its scene side is scene/quad_light.h): stratified samples of
// its area, and its front as rays meet it.
#include "rtpro/core/ray.h"
#include "light_sample_value.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/quad_light.h"

namespace rtpro {

inline int samples_per_axis(const QuadLight& light) { return light.samples_per_axis; }

// Uniform over the area; `u` is a point of [0,1)².
LightSample sample_light_of_kind(const QuadLight& light, const Vec3& point, Sample2D u);

// The ray parameter of a hit on its front in (ray.tnear, t_max), or kLightMissed: it emits on one
// side only.
float hit_light_of_kind(const QuadLight& light, const Ray& ray, float t_max);

inline Color emission_of_kind(const QuadLight& light) { return light.radiance; }

}  // namespace rtpro
