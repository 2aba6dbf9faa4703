#pragma once
// The isotropic Trowbridge-Reitz (GGX) microfacet distribution shared by the rough conductor and
// the rough dielectric, in the local shading frame (macro normal +z), and its directional albedo,
// which the conductor's multiple-scattering compensation needs.
#include "rtpro/core/vec3.h"
#include "rtpro/render/sampler.h"

#include <algorithm>
#include <optional>

namespace rtpro {

// Below this α a surface is treated as perfectly smooth (delta lobes): the lobe is narrower than
// anything an image resolves, and sampling it as a distribution would only invite float trouble
// in D's 1/α² peak (pbrt-v4's EffectivelySmooth).
inline constexpr float kSmoothAlpha = 1e-3f;

// Schlick's Fresnel weight (1 − cos θ)⁵, with cos θ clamped to [0, 1].
inline float schlick_weight(float cos_theta) {
  const float m = 1.0f - std::clamp(cos_theta, 0.0f, 1.0f);
  return (m * m) * (m * m) * m;
}

// glTF / Disney: α = roughness², so the perceived roughness changes evenly along the slider.
float roughness_to_alpha(float roughness);

struct GgxDistribution {
  float alpha;

  bool effectively_smooth() const { return alpha < kSmoothAlpha; }

  // Microfacet normal density per unit solid angle of wm, normalised so ∫ D(wm) cos θm dωm = 1.
  float d(const Vec3& wm) const;
  // Smith's auxiliary function: the shadowed area per unit visible area seen from w.
  float lambda(const Vec3& w) const;
  float g1(const Vec3& w) const { return 1.0f / (1.0f + lambda(w)); }
  // Height-correlated masking-shadowing: a facet hidden from wo is likelier hidden from wi too,
  // which the separable G1(wo)·G1(wi) ignores (Heitz 2014).
  float g(const Vec3& wo, const Vec3& wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

  // The distribution of normals visible from w, D_w(wm) = G1(w) / |cos θ| · D(wm) · (w·wm)⁺, over
  // normals wm in the upper hemisphere; w may lie below (the surface is seen from inside).
  float visible_normal_pdf(const Vec3& w, const Vec3& wm) const;
  // A normal wm (upper hemisphere) distributed as visible_normal_pdf(w, ·): Heitz 2018,
  // "Sampling the GGX Distribution of Visible Normals".
  Vec3 sample_visible_normal(const Vec3& w, Sample2D u) const;
};

// E(μ, α): the fraction of light a GGX mirror-facet surface (Fresnel = 1) reflects after a single
// scattering, for incidence cos θ = μ. What is missing, 1 − E, is the energy that in reality
// scatters more than once. Looked up bilinearly in a table integrated ahead of time (energy_tables.h).
float ggx_directional_albedo(float mu, float alpha);
// E_avg(α) = 2 ∫ E(μ, α) μ dμ, exactly the integral of the table's interpolation, so a lobe built
// from 1 − E(μ) normalised by 1 − E_avg carries exactly the energy it should.
float ggx_average_albedo(float alpha);

// A GGX reflection lobe's pieces, for the lobes that mix one with others:
// The facet normal that reflects wo into wi, facing +z, or nothing for wi = −wo.
std::optional<Vec3> reflection_normal(const Vec3& wo, const Vec3& wi);
// D G / (4 |cos θo| |cos θi|): a GGX reflection without its Fresnel term.
float microfacet_reflection(const GgxDistribution& ggx, const Vec3& wo, const Vec3& wi, const Vec3& wm);
// Visible normals reflected: dωm/dωi = 1 / (4 |wo·wm|).
float reflection_density(const GgxDistribution& ggx, const Vec3& wo, const Vec3& wm);
// A reflected direction from a visible normal; nothing where the facet sends it into the surface.
std::optional<Vec3> sample_reflection(const GgxDistribution& ggx, const Vec3& wo, Sample2D u);

}  // namespace rtpro
