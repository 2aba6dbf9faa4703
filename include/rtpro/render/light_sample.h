#pragma once
// What shading needs from a light at a point: where it is and what arrives. Each light kind in
// the Light variant adds one overload of sample() in light_sample.cpp; shading never names a kind.
#include "rtpro/core/vec3.h"
#include "rtpro/scene/light.h"

namespace rtpro {

struct LightSample {
  Vec3 direction;  // unit, from the point towards the light
  float distance;  // to the light; infinity for directional lights
  Color radiance;  // arriving at the point
};

LightSample sample_light(const Light& light, const Vec3& point);

}  // namespace rtpro
