#pragma once
// What the whitted integrator shades a material with besides its colour: the Phong highlight, the
// mirror and glass. Every kind of material gives its own (whitted_approximation_of, in the kind's
// header: scene/phong_material.h), physically based kinds approximated, so the whitted integrator
// renders any scene (a preview; `path` renders it as it is).
#include "rtpro/core/vec3.h"

#include <algorithm>
#include <optional>

namespace rtpro {

// A smooth dielectric (glass, water): refraction index and interior absorption. The path
// integrator reads the absorption too, for paths inside it.
struct Dielectric {
  float ior = 1.5f;
  Color transmittance{1.0f};  // of white light after `transmittance_distance`
  float transmittance_distance = 1.0f;
};

struct WhittedFields {
  float specular;      // Phong highlight weight
  float shininess;     // Phong exponent
  float reflectivity;  // weight of the mirror reflection
  std::optional<Dielectric> glass;
  float color_scale = 1.0f;  // the share of the material's colour its diffuse part keeps
};

// The Phong exponent whose lobe is about as wide as a GGX lobe of this roughness (alpha =
// roughness²; Walter et al. 2007).
inline float phong_exponent_of_roughness(float roughness) {
  const float alpha = roughness * roughness;
  return std::min(2.0f / std::max(alpha * alpha, 1e-4f) - 2.0f, 10000.0f);
}

}  // namespace rtpro
