#pragma once
// A metal: GGX microfacet reflection with a conductor's Fresnel term, given either as an artist's
// colour at normal incidence (Schlick's approximation) or as a measured complex index η + iκ per
// RGB channel (exact). α below kSmoothAlpha is a perfect mirror (a delta lobe).
//
// A single-scattering microfacet model loses the light that bounces between facets more than once
// (at α = 1 a perfect reflector returns as little as 31%, at normal incidence), so rough metals
// render too dark; Kulla and Conty's compensation (2017) adds a diffuse-like lobe carrying exactly
// that energy, tinted by the Fresnel term's average.
#include "bsdf_from.h"
#include "bsdf_sample.h"
#include "microfacet.h"

#include <optional>

namespace rtpro {

class ConductorBsdf {
 public:
  // `f0`: reflectance at normal incidence, each channel in [0, 1].
  static ConductorBsdf from_f0(const Color& f0, float alpha, bool energy_compensation = true);
  // `eta`, `k`: the metal's complex index relative to the outside medium, per channel.
  static ConductorBsdf from_complex_ior(const Color& eta, const Color& k, float alpha, bool energy_compensation = true);

  float alpha() const { return ggx_.alpha; }
  bool energy_compensation() const { return energy_compensation_; }
  bool is_delta() const { return ggx_.effectively_smooth(); }
  // α raised to at least min_alpha, the compensation lobe with it (render/bsdf/bsdf.h, roughen_bsdf).
  void roughen_to(float min_alpha);
  // It reflects on whichever side wo is: the frame's +z is the side the ray came from.
  bool needs_outward_frame() const { return false; }

  // Reflectance of a perfectly smooth facet lit at cos θ to its normal.
  Color fresnel(float cos_theta) const;
  // 2 ∫ F(μ) μ dμ: the reflectance averaged over cosine-weighted incidence.
  Color fresnel_average() const { return fresnel_average_; }

  // Reflection only, on either side of the surface (a metal has no inside).
  Color eval(const Vec3& wo, const Vec3& wi) const;
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // u_lobe picks between the microfacet lobe (visible normals) and, with compensation, the
  // cosine-distributed multiple-scattering lobe; f and pdf are always those of the whole BSDF.
  std::optional<BsdfSample> sample(const Vec3& wo, float u_lobe, Sample2D u) const;

 private:
  enum class FresnelModel { kSchlick, kComplexIor };
  // What eval, pdf and sample need of wo alone.
  struct Outgoing {
    float cos_o;     // |cos θo|
    float albedo;    // E(μo), or 1 without compensation
    float p_single;  // the chance of sampling the microfacet lobe: its share of the estimated albedo
  };
  // ... and of the pair wo, wi (on the same side).
  struct Geometry {
    Vec3 wm;                 // the half vector, facing +z
    float cos_i, wo_dot_wm;  // absolute values
  };

  ConductorBsdf(FresnelModel model, const Color& f0, const Color& eta, const Color& k, float alpha,
                bool energy_compensation);
  bool compensates() const { return energy_compensation_ && !ggx_.effectively_smooth(); }
  Outgoing outgoing(const Vec3& wo) const;
  std::optional<Geometry> geometry(const Vec3& wo, const Vec3& wi) const;
  Color value(const Vec3& wo, const Vec3& wi, const Outgoing& o, const Geometry& g) const;
  float density(const Vec3& wo, const Outgoing& o, const Geometry& g) const;

  FresnelModel model_;
  Color f0_, eta_, k_;
  GgxDistribution ggx_;
  bool energy_compensation_;
  Color fresnel_average_;
  float average_albedo_;            // E_avg(α)
  Color multiple_scattering_tint_;  // F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg))
};

// Exact reflectance of a conductor with complex index eta + i·k (relative to the incident medium)
// for one channel, lit at cos θ (pbrt-v4's FrComplex).
float fresnel_complex(float cos_theta, float eta, float k);

struct ConductorSurface;  // scene/conductor_material.h

// As render/bsdf/bsdf_from.h asks of every kind.
Vec3 bsdf_from(const ConductorSurface& model, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);
inline bool makes_lambert_bsdf(const ConductorSurface&) { return false; }

}  // namespace rtpro
