#pragma once
// Blackbody emission as Cycles' Principled Volume gives it (blackbody intensity 1, a white tint):
// the Stefan–Boltzmann exitance σT⁴ as radiance (÷π), scaled by 1e-6 as Cycles scales it, in the
// colour of Planck's spectrum at T (linear Rec.709, luminance 1).
#include "rtpro/core/vec3.h"

namespace rtpro {

// The colour of a blackbody at `kelvin` with luminance (Rec.709 Y) 1; temperatures are clamped to
// [800, 12000] K, Cycles' range.
Color blackbody_color(float kelvin);

// Radiance emitted per unit length at `kelvin` (0 at or below 0 K).
Color blackbody_emission(float kelvin);

}  // namespace rtpro
