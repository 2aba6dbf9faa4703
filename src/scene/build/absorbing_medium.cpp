#include "rtpro/scene/absorbing_medium.h"

#include "rtpro/scene/dielectric.h"

namespace rtpro {

std::optional<AbsorbingMedium> glass_absorption(const Dielectric& glass) {
  if (glass.transmittance == Color(1.0f)) return std::nullopt;
  return AbsorbingMedium{glass.transmittance, glass.transmittance_distance};
}

}  // namespace rtpro
