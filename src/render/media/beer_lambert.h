#pragma once
// Absorption inside a dielectric, given the way users think of it (pbrt/Mitsuba/POV-Ray style):
// the colour white light has after travelling `reference_distance` through the medium.
#include "rtpro/core/vec3.h"

namespace rtpro {

// Transmittance after `distance` = colour^(distance / reference_distance) per channel, i.e.
// exp(-σ·distance) with σ = -ln(colour) / reference_distance. A channel of 0 stays 0 (opaque).
Vec3 beer_lambert_transmittance(const Vec3& colour_at_reference, float reference_distance, float distance);

}  // namespace rtpro
