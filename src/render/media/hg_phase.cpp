#include "hg_phase.h"

#include "rtpro/core/math_constants.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

float henyey_greenstein(float cos_theta, float g) {
  const float denominator = 1.0f + g * g - 2.0f * g * cos_theta;
  return (1.0f - g * g) / (4.0f * kPi * denominator * std::sqrt(std::max(denominator, 0.0f)));
}

}  // namespace rtpro
