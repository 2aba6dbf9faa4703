#pragma once
// The Henyey–Greenstein phase function, with directions as light travels: `incoming` is the
// direction the light (the path's ray) was travelling when it reached the point, `outgoing` the
// direction it leaves in, so g > 0 favours carrying on (forward scattering) and g < 0 turning back.
// pbrt-v4's HGPhaseFunction (util/scattering.h) in that convention; sampling inverts the
// distribution of cos θ exactly, so its pdf is its value.
#include "rtpro/core/math_constants.h"
#include "rtpro/core/vec3.h"
#include "rtpro/render/sampler.h"
#include "shading_frame.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

// p(cos θ) = (1 − g²) / (4π (1 + g² − 2g cos θ)^{3/2}), θ between incoming and outgoing; integrates
// to 1 over the sphere. -1 < g < 1.
float henyey_greenstein(float cos_theta, float g);

struct PhaseSample {
  Vec3 outgoing;  // unit
  float pdf;      // per unit solid angle, = the phase function's value
};

// A direction from the phase function about unit `incoming`, from the two numbers u. Inline: its
// PhaseSample returned from out of line is put together on the stack a float at a time and
// loaded back in pairs, a store-forwarding stall.
inline PhaseSample sample_henyey_greenstein(const Vec3& incoming, float g, Sample2D u) {
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
