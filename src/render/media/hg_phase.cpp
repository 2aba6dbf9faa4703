#include "hg_phase.h"

#include "rtpro/core/math_constants.h"
#include "shading_frame.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

float henyey_greenstein(float cos_theta, float g) {
  const float denominator = 1.0f + g * g - 2.0f * g * cos_theta;
  return (1.0f - g * g) / (4.0f * kPi * denominator * std::sqrt(std::max(denominator, 0.0f)));
}

PhaseSample sample_henyey_greenstein(const Vec3& incoming, float g, Sample2D u) {
  // The inverse of the distribution of cos θ; isotropic below |g| = 1e-3, where the inverse loses
  // its digits to cancellation.
  float cos_theta;
  if (std::fabs(g) < 1e-3f) {
    cos_theta = 1.0f - 2.0f * u.x;
  } else {
    const float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u.x);
    cos_theta = (1.0f + g * g - s * s) / (2.0f * g);
  }
  cos_theta = std::clamp(cos_theta, -1.0f, 1.0f);
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float phi = 2.0f * kPi * u.y;
  const ShadingFrame frame = ShadingFrame::from_normal(incoming);
  const Vec3 outgoing = frame.to_world({sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta});
  return {outgoing, henyey_greenstein(cos_theta, g)};
}

}  // namespace rtpro
