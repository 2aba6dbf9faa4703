#pragma once
// A smooth dielectric (glass, water): its refraction index and what it absorbs inside. A kind of
// material whose inside is such a medium says so (interior_of, in the kind's header:
// scene/dielectric_material.h): the scene's build makes its absorption a medium
// (glass_absorption, scene/absorbing_medium.h), which the path integrator tracks paths through; the whitted integrator's
// glass is its Whitted approximation's (scene/whitted_material.h).
#include "rtpro/core/vec3.h"

namespace rtpro {

struct Dielectric {
  float ior = 1.5f;
  Color transmittance{1.0f};  // of white light after `transmittance_distance`
  float transmittance_distance = 1.0f;
};

}  // namespace rtpro
