#include "rtpro/scene/dielectric.h"

#include <cmath>
#include <limits>

namespace rtpro {

std::optional<HomogeneousMedium> beer_lambert_medium(const Dielectric& glass) {
  if (glass.transmittance == Color(1.0f)) return std::nullopt;
  const auto sigma = [&](float kept) {
    const float s = -std::log(kept) / glass.transmittance_distance;
    return std::isfinite(s) ? s : std::numeric_limits<float>::max();
  };
  HomogeneousMedium medium;
  medium.sigma_a = {sigma(glass.transmittance.x), sigma(glass.transmittance.y), sigma(glass.transmittance.z)};
  return medium;
}

}  // namespace rtpro
