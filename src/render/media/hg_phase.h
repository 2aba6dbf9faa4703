#pragma once
// The Henyey–Greenstein phase function, with directions as light travels: `incoming` is the
// direction the light (the path's ray) was travelling when it reached the point, `outgoing` the
// direction it leaves in, so g > 0 favours carrying on (forward scattering) and g < 0 turning back.
// pbrt-v4's HGPhaseFunction (util/scattering.h) in that convention; sampling inverts the
// distribution of cos θ exactly, so its pdf is its value.
#include "rtpro/core/vec3.h"
#include "rtpro/render/sampler.h"

namespace rtpro {

// p(cos θ) = (1 − g²) / (4π (1 + g² − 2g cos θ)^{3/2}), θ between incoming and outgoing; integrates
// to 1 over the sphere. -1 < g < 1.
float henyey_greenstein(float cos_theta, float g);

struct PhaseSample {
  Vec3 outgoing;  // unit
  float pdf;      // per unit solid angle, = the phase function's value
};

// A direction from the phase function about unit `incoming`, from the two numbers u.
PhaseSample sample_henyey_greenstein(const Vec3& incoming, float g, Sample2D u);

}  // namespace rtpro
