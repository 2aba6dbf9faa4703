#pragma once
// The render side of an absorbing medium (scene/absorbing_medium.h): transmittance in closed form,
// transmittance^(d / distance) per channel (render/bsdf/beer_lambert.h, which the Whitted
// integrator's glass uses too), so a path through tinted glass is attenuated exactly as a glass's
// absorption always was; nothing scatters, so no walk ever asks for its points or majorants but
// ratio tracking's tests.
#include "beer_lambert.h"
#include "medium_interface.h"
#include "rtpro/scene/absorbing_medium.h"

#include <cmath>
#include <limits>
#include <optional>

namespace rtpro {

// σa = −ln(transmittance) / distance (an opaque channel the largest float).
inline Color absorption_coefficients(const AbsorbingMedium& medium) {
  const auto sigma = [&](float kept) {
    const float s = -std::log(kept) / medium.distance;
    return std::isfinite(s) ? s : std::numeric_limits<float>::max();
  };
  return {sigma(medium.transmittance.x), sigma(medium.transmittance.y), sigma(medium.transmittance.z)};
}

inline MediumPoint medium_point(const AbsorbingMedium& medium, const Vec3&) {
  return {absorption_coefficients(medium), Color(0.0f), Color(0.0f), 0.0f};
}

inline SingleMajorant majorants(const AbsorbingMedium& medium, const Ray& ray, float t_max) {
  return {ray.tnear, t_max, max_component(absorption_coefficients(medium))};
}

inline bool only_absorbs(const AbsorbingMedium&) { return true; }

inline std::optional<Color> closed_form_transmittance(const AbsorbingMedium& medium, const Ray& ray, float t_max) {
  return beer_lambert_transmittance(medium.transmittance, medium.distance, t_max - ray.tnear);
}

}  // namespace rtpro
