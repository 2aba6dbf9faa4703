#pragma once
// The render side of a homogeneous medium (scene/homogeneous_medium.h): the same coefficients at
// every point, one majorant segment (its largest extinction) over the whole ray, and Beer–Lambert
// transmittance in closed form.
#include "medium_interface.h"
#include "rtpro/scene/homogeneous_medium.h"

#include <cmath>
#include <optional>

namespace rtpro {

inline MediumPoint medium_point(const HomogeneousMedium& medium, const Vec3&) {
  return {medium.sigma_a, medium.sigma_s, medium.emission, medium.anisotropy};
}

inline SingleMajorant majorants(const HomogeneousMedium& medium, const Ray& ray, float t_max) {
  return {ray.tnear, t_max, max_component(medium.sigma_a + medium.sigma_s)};
}

inline bool only_absorbs(const HomogeneousMedium& medium) {
  const auto zero = [](const Color& c) { return c.x == 0.0f && c.y == 0.0f && c.z == 0.0f; };
  return zero(medium.sigma_s) && zero(medium.emission);
}

// exp(-σt·d) per channel over d = t_max - tnear. A channel that does not attenuate transmits all
// of an infinite ray, and a distance of 0 all of any channel (0 × ∞ would be NaN either way: an
// opaque channel's σt is the largest float).
inline std::optional<Color> closed_form_transmittance(const HomogeneousMedium& medium, const Ray& ray, float t_max) {
  const float distance = t_max - ray.tnear;
  const Color sigma_t = medium.sigma_a + medium.sigma_s;
  const auto channel = [&](float sigma) {
    return sigma > 0.0f && distance > 0.0f ? std::exp(-sigma * distance) : 1.0f;
  };
  return Color{channel(sigma_t.x), channel(sigma_t.y), channel(sigma_t.z)};
}

}  // namespace rtpro
