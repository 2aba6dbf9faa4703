#pragma once
// A hair fibre's absorption coefficient σa (per unit of its radius, pbrt's convention) from what
// artists give instead: pigment concentrations, or the colour the fibre should have.
#include "rtpro/core/vec3.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

// Eumelanin (brown to black) and pheomelanin (red) concentrations, pbrt-v4's
// SigmaAFromConcentration: Donner and Jensen's pigments' absorption at the sRGB primaries. Blonde
// is about 0.3 eumelanin, brown 1.3, black 8.
inline Color hair_sigma_a_from_melanin(float eumelanin, float pheomelanin) {
  return Color(0.419f, 0.697f, 1.37f) * eumelanin + Color(0.187f, 0.4f, 1.05f) * pheomelanin;
}

namespace hair_absorption_detail {
// Chiang et al.'s fit of ln(colour) / sqrt(σa) to the multiply scattered colour of a fibre of
// azimuthal roughness β_n.
inline float colour_fit(float beta_n) {
  const float b = beta_n;
  return 5.969f - 0.215f * b + 2.532f * b * b - 10.73f * b * b * b + 5.574f * b * b * b * b +
         0.245f * b * b * b * b * b;
}
}  // namespace hair_absorption_detail

// pbrt-v4's SigmaAFromReflectance: the σa whose hair, many fibres deep, looks `colour`. A channel
// of 0 is taken as 1e-4 (σa about 30), so that σa stays finite.
inline Color hair_sigma_a_from_color(const Color& colour, float beta_n) {
  const float fit = hair_absorption_detail::colour_fit(beta_n);
  Color sigma_a;
  for (int c = 0; c < 3; ++c) {
    const float root = std::log(std::clamp(colour[c], 1e-4f, 1.0f)) / fit;
    sigma_a[c] = root * root;
  }
  return sigma_a;
}

// Its inverse: the colour hair of absorption σa shows (the albedo AOV's and the Whitted colour).
inline Color hair_color_from_sigma_a(const Color& sigma_a, float beta_n) {
  const float fit = hair_absorption_detail::colour_fit(beta_n);
  return {std::exp(-std::sqrt(sigma_a.x) * fit), std::exp(-std::sqrt(sigma_a.y) * fit),
          std::exp(-std::sqrt(sigma_a.z) * fit)};
}

}  // namespace rtpro
