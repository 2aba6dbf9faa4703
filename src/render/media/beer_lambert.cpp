#include "beer_lambert.h"

#include <cmath>

namespace rtpro {

Vec3 beer_lambert_transmittance(const Vec3& colour_at_reference, float reference_distance, float distance) {
  const float exponent = distance / reference_distance;
  return {std::pow(colour_at_reference.x, exponent), std::pow(colour_at_reference.y, exponent),
          std::pow(colour_at_reference.z, exponent)};
}

}  // namespace rtpro
