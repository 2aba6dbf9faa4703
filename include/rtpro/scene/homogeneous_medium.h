#pragma once
// A homogeneous medium (`interior: {sigma_a: ..., sigma_s: ..., anisotropy: g}`): the same
// absorption, scattering, phase function and emission everywhere inside its boundary. Its scene
// side (this header) is its data; its render side is render/media/homogeneous_medium.h.
#include "rtpro/core/vec3.h"

namespace rtpro {

struct HomogeneousMedium {
  Color sigma_a{0.0f};      // absorption coefficient per scene unit, per channel
  Color sigma_s{0.0f};      // scattering coefficient per scene unit, per channel
  float anisotropy = 0.0f;  // Henyey–Greenstein g, -1 < g < 1: > 0 scatters forward
  // Radiance added per unit of length travelled (Cycles' volume emission; pbrt's σa·Le).
  Color emission{0.0f};
};

}  // namespace rtpro
