#pragma once
// What the whitted integrator shades a material with, and nothing else reads: a diffuse colour, the
// Phong highlight, the mirror and glass. Every kind of material makes its own
// (whitted_approximation_of, in the kind's header: scene/phong_material.h), physically based kinds
// approximated, so the whitted integrator renders any scene (a preview; `path` renders it as it is).
#include "rtpro/scene/dielectric.h"
#include "rtpro/scene/material_textures.h"

#include <algorithm>
#include <optional>

namespace rtpro {

struct WhittedMaterial {
  ColorTexture color;               // diffuse and ambient colour
  float specular;                   // Phong highlight weight
  float shininess;                  // Phong exponent
  float reflectivity;               // weight of the mirror reflection
  std::optional<Dielectric> glass;  // no diffuse part: Fresnel-weighted reflection and refraction
};

// The Phong exponent whose lobe is about as wide as a GGX lobe of this roughness (alpha =
// roughness²; Walter et al. 2007).
inline float phong_exponent_of_roughness(float roughness) {
  const float alpha = roughness * roughness;
  return std::min(2.0f / std::max(alpha * alpha, 1e-4f) - 2.0f, 10000.0f);
}

}  // namespace rtpro
