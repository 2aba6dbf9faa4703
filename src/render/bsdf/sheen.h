#pragma once
// The "Charlie" sheen of Estevez and Kulla (2017, "Production Friendly Microfacet Sheen BRDF"), as
// KHR_materials_sheen specifies it: the back-scattering of velvet and cloth, modelled as a
// microfacet lobe whose normals belong to fibres standing up from the surface, so they lie mostly
// sideways: D ∝ sin^(1/α) θm. Its Λ is the paper's fit, and the lobe is symmetric in wo and wi.
// The layer's directional albedo E(μ) is what the material under the sheen does not receive
// (KHR_materials_sheen's albedo scaling).
#include "rtpro/core/vec3.h"

namespace rtpro {

// α = roughness², held above a floor: at α → 0 the fibres stand perfectly straight and the lobe
// becomes an infinitely thin spike at the horizon that nothing can integrate or sample (three.js
// holds the roughness at 0.07 for the same reason).
float sheen_roughness_to_alpha(float roughness);

struct CharlieSheen {
  float alpha;

  // Normalised so that ∫ D(wm) cos θm dωm = 1 over the upper hemisphere.
  float d(const Vec3& wm) const;
  float lambda(float abs_cos_theta) const;
  // D G / (4 |cos θo| |cos θi|) with G = 1 / (1 + Λ(wo) + Λ(wi)), for wo and wi on the same side
  // (either side: a sheen has no inside); 0 otherwise. Without the colour.
  float eval(const Vec3& wo, const Vec3& wi) const;
};

// E(μ, roughness) = ∫ CharlieSheen::eval · |cos θi| dωi at |cos θo| = μ. It exceeds 1 for smooth
// sheens seen at grazing angles (2.8 at roughness 0.07, μ = 0.001; above 1 up to roughness 0.25):
// the fit of Λ lets the fibres reflect more than they receive there.
float sheen_directional_albedo(float mu, float roughness);

// The sheen as a material layer uses it: CharlieSheen divided by max(1, 1.05·E(μo), 1.05·E(μi)),
// which is the lobe itself wherever it conserves energy, symmetric in wo and wi, and never
// reflects more than it receives (its albedo at wo is at most E(μo) / max(1, 1.05·E(μo)); the 5%
// covers the table's interpolation of E). Both E and the bounded lobe's albedo Ē come from tables
// integrated ahead of time (energy_tables.h) and read bilinearly.
class SheenLobe {
 public:
  explicit SheenLobe(float roughness);

  float eval(const Vec3& wo, const Vec3& wi) const;
  // Ē(μ): what the layer reflects of light arriving at |cos θ| = μ, so 1 − Ē is what passes.
  float albedo(float mu) const;

 private:
  float roughness_;
  CharlieSheen charlie_;
};

}  // namespace rtpro
