#pragma once
// A medium that only absorbs, given as users of glass give it (pbrt, Mitsuba, POV-Ray; glTF's
// KHR_materials_volume): the colour white light has after travelling `distance` through it, so
// σa = −ln(transmittance) / distance per channel. A glass's `transmittance:` is one, and so is a
// glTF volume's attenuationColor and attenuationDistance. Its scene side (this header) is its
// data; its render side is render/media/absorbing_medium.h.
#include "rtpro/core/vec3.h"

#include <optional>

namespace rtpro {

struct Dielectric;  // scene/dielectric.h

struct AbsorbingMedium {
  Color transmittance{1.0f};  // of white light after `distance`; a channel of 0 is opaque
  float distance = 1.0f;      // scene units, > 0
};

// The medium inside a glass (its transmittance over its transmittance_distance); nothing for
// clear glass.
std::optional<AbsorbingMedium> glass_absorption(const Dielectric& glass);

}  // namespace rtpro
