#pragma once
// The directional albedo of a GGX reflection whose Fresnel term is Schlick's
// F(c) = F0 + (F90 − F0)(1 − c)⁵, c the cosine between wo and the facet normal: the share of light
// a dielectric specular layer (glTF's, a clear coat's) reflects in a single scattering, which is
// what the layers under it do not receive. The integral is linear in F0 and F90, so two tables
// (over μ = |cos θo| and α) serve every colour and every ior: E = F0·(E₁ − E₅) + F90·E₅, with
// E₁ = ∫ D G / (4 μo) dωi (ggx_directional_albedo's integral) and E₅ the same weighted by (1 − c)⁵.
#include "rtpro/core/vec3.h"

namespace rtpro {

struct SchlickAlbedo {
  float f0_weight;   // E₁ − E₅: what F0 contributes
  float f90_weight;  // E₅: what F90 contributes

  float operator()(float f0, float f90) const { return f0 * f0_weight + f90 * f90_weight; }
  Color operator()(const Color& f0, float f90) const { return f0 * f0_weight + Color(f90 * f90_weight); }
};

// E(μ, α) for incidence |cos θo| = μ. Below kSmoothAlpha the closed form of a mirror, E = F(μ);
// otherwise looked up bilinearly in tables integrated ahead of time (energy_tables.h).
SchlickAlbedo ggx_schlick_albedo(float mu, float alpha);
// 2 ∫ E(μ, α) μ dμ, exactly the integral of what ggx_schlick_albedo interpolates, so that a lobe
// built from 1 − E(μ) and normalised by 1 − E_avg carries exactly the energy the layer leaves.
SchlickAlbedo ggx_schlick_average_albedo(float alpha);

}  // namespace rtpro
