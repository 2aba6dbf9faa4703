#pragma once
// What shading gets from one sample of a light (render/lights/light_sample.h): each kind's sampling
// (render/lights/point_light_sample.h and its neighbours) returns one.
#include "rtpro/core/vec3.h"

#include <limits>

namespace rtpro {

struct LightSample {
  Vec3 direction;  // unit, from the point towards the light
  float distance;  // to the light; infinity for directional lights
  // Arriving at the point along `direction`, as the estimate of the whole light from this one
  // sample (1 / pdf in solid angle folded in); zero when nothing arrives (behind a one-sided
  // light, inside a sphere light). Average over the light's samples.
  Color radiance;
};

// What a light's hit test (hit_light_of_kind, hit_light) returns where the ray does not meet it:
// infinity, which no hit in (tnear, t_max) can equal, so `t < t_max` tells a hit.
constexpr float kLightMissed = std::numeric_limits<float>::infinity();

}  // namespace rtpro
