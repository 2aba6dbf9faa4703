#pragma once
// glTF 2.0's metallic-roughness material (the specification's Appendix B) with the extensions
// KHR_materials_ior, _specular, _transmission, _clearcoat and _sheen, as one BSDF kind. The layers,
// top to bottom:
//
//   coat        GGX reflection, F0 0.04 (ior 1.5), α = coat_roughness², weight coat_weight
//   fuzz        the Charlie sheen (render/bsdf/sheen.h) of colour fuzz_color
//   material =  mix(dielectric, metal, metalness)
//     metal       ConductorBsdf::from_f0(base_color, α), with its Kulla-Conty compensation
//     dielectric  GGX reflection with Schlick's F, F0 = min(((ior−1)/(ior+1))²·specular_color, 1)·specular_weight
//                 and F90 = specular_weight, over mix(mix(Lambert(base_color), subsurface, subsurface),
//                 rough transmission tinted by base_color, transmission_weight)
//
// with α = roughness² (the same GGX roughness for the specular layer, the metal and the
// transmission). A layer passes on what it does not reflect, and that is what the layers below
// receive (albedo scaling, as OpenPBR, Cycles and KHR_materials_sheen do it): the coat scales all
// below it by 1 − coat_weight·E_coat(μo), the fuzz by 1 − max(fuzz_color)·E_fuzz(μo), E being the
// layer's directional albedo (so these two follow wo alone and are not reciprocal). Under the
// dielectric's specular layer the Lambert lobe is base_color·(1 − E(μo))(1 − E(μi)) / (π (1 − E_avg))
// per channel (Kelemen and Szirmay-Kalos): it reflects exactly base_color·(1 − E(μo)), the energy
// the layer leaves, and stays reciprocal. (KHR_materials_specular takes 1 − the largest channel of
// F for the base; per channel each channel keeps its energy.) The transmission splits by Fresnel
// facet by facet instead (Walter et al.), and carries the radiance scale 1/η² as DielectricBsdf;
// seen from inside, its Schlick F takes the refracted angle and is 1 beyond the critical angle.
// A white dielectric thus reflects all it receives at any roughness, where Appendix B's
// per-half-vector fresnel_mix, with the base weighted by 1 − F(V·H), reflects up to 1.35 at grazing
// incidence (roughness 0.3, μo = 0.03) and 0.96 at normal incidence.
//
// The subsurface lobe receives what the Lambert lobe would, base_color·(1 − E(μo)), without the
// base colour: a sample of it hands the path to a random walk under the surface, whose scattering
// albedo makes that colour (render/integrators/subsurface_walk.h); it has no f of its own to
// evaluate, so light sampling at the entry point leaves it out (the walk's exit samples lights).
//
// Surfaces whose α is below kSmoothAlpha become delta lobes (mirror reflection, straight
// refraction), as in ConductorBsdf and DielectricBsdf.
//
// The frame: the opaque part (no transmission) reflects on whichever side wo is, like DiffuseBsdf
// and ConductorBsdf. With transmission_weight > 0, +z must be the outside, as for DielectricBsdf:
// needs_outward_frame() says when the caller must build the frame from the outward normal.
#include "bsdf_from.h"
#include "bsdf_sample.h"
#include "conductor_bsdf.h"
#include "microfacet.h"
#include "sheen.h"

#include <algorithm>
#include <array>
#include <optional>

namespace rtpro {

// The glTF 2.0 metallic-roughness model and the extensions tinygltf hands over, with OpenPBR's
// parameter names where one exists. Values already evaluated at the shading point (textures applied).
struct PrincipledParameters {
  Color base_color{0.8f};            // glTF baseColorFactor (× texture)
  float metalness = 0.0f;            // glTF metallicFactor
  float roughness = 0.5f;            // glTF roughnessFactor; GGX alpha = roughness²
  float ior = 1.5f;                  // KHR_materials_ior (dielectric F0 = ((ior−1)/(ior+1))², 0.04 at 1.5)
  float specular_weight = 1.0f;      // KHR_materials_specular specularFactor
  Color specular_color{1.0f};        // KHR_materials_specular specularColorFactor
  float transmission_weight = 0.0f;  // KHR_materials_transmission transmissionFactor
  float coat_weight = 0.0f;          // KHR_materials_clearcoat clearcoatFactor
  float coat_roughness = 0.0f;       // KHR_materials_clearcoat clearcoatRoughnessFactor
  Color fuzz_color{0.0f};            // KHR_materials_sheen sheenColorFactor (OpenPBR "fuzz")
  float fuzz_roughness = 0.0f;       // KHR_materials_sheen sheenRoughnessFactor
  float subsurface_weight = 0.0f;    // Blender's Principled BSDF Subsurface (Weight)
};

class PrincipledBsdf {
 public:
  // Weights and colours are clamped to [0, 1], roughnesses to [0, 1], ior to at least 1.
  explicit PrincipledBsdf(const PrincipledParameters& parameters);

  // True when every lobe that contributes is specular (e.g. a metal, or a clear glass, of
  // roughness 0 without fuzz).
  bool is_delta() const;
  // With transmission the surface has an inside: +z of the shading frame must point outwards.
  bool needs_outward_frame() const { return transmission_ > 0.0f; }
  // The specular, metal, transmission and coat lobes' α raised to at least min_alpha; the sheen
  // keeps its own (render/bsdf/bsdf.h, roughen_bsdf).
  void roughen_to(float min_alpha) {
    if (ggx_.alpha < min_alpha) {
      ggx_.alpha = min_alpha;
      metal_ = ConductorBsdf::from_f0(base_color_, min_alpha, metalness_ > 0.0f);
      normalize_diffuse();
    }
    coat_ggx_.alpha = std::max(coat_ggx_.alpha, min_alpha);
    find_sampled_with_density();
  }

  // f without the cosine, summed over the non-delta lobes.
  Color eval(const Vec3& wo, const Vec3& wi) const;
  // The density of sample() choosing wi through any non-delta lobe: the lobe-choice
  // probabilities times each lobe's density, summed.
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // u_lobe chooses a lobe in proportion to an estimate of its albedo at wo (coat, fuzz, specular,
  // diffuse, transmission, metal, subsurface), and, rescaled within the lobe's share, the metal's own
  // sub-lobe. For a non-delta lobe f and pdf are those of the whole BSDF, as eval() and pdf()
  // give them; a delta sample carries every smooth lobe sharing its direction.
  std::optional<BsdfSample> sample(const Vec3& wo, float u_lobe, Sample2D u) const;

 private:
  enum Lobe { kCoat, kFuzz, kSpecular, kDiffuse, kTransmission, kMetal, kSubsurface, kLobeCount };

  // What eval, pdf and sample need of wo alone.
  struct Outgoing {
    float cos_o;                      // |cos θo|
    Color specular_albedo;            // E(μo) of the dielectric's specular layer, per channel
    float below_coat;                 // 1 − coat_weight·E_coat(μo)
    float below_fuzz;                 // below_coat·(1 − max(fuzz_color)·E_fuzz(μo)): what the material receives
    float glass_compensation = 1.0f;  // 1/E(μo) of the rough glass (render/bsdf/dielectric_albedo.h)
    std::array<float, kLobeCount> probability;
  };

  bool lobe_is_delta(Lobe lobe) const;
  static BsdfLobe lobe_kind(Lobe lobe) {
    switch (lobe) {
      case kFuzz:
      case kDiffuse: return BsdfLobe::kDiffuse;
      case kTransmission: return BsdfLobe::kTransmission;
      case kSubsurface: return BsdfLobe::kSubsurface;
      case kCoat:
      case kSpecular:
      case kMetal:
      case kLobeCount: break;
    }
    return BsdfLobe::kGlossy;
  }
  // What follows from the specular layer's α: the Lambert base's normalisation, and which lobes
  // are sampled with a density.
  void normalize_diffuse();
  bool has_specular_layer() const;
  void find_sampled_with_density() {
    for (int k = 0; k < kLobeCount; ++k) sampled_with_density_[k] = active_[k] && !lobe_is_delta(static_cast<Lobe>(k));
  }
  Outgoing outgoing(const Vec3& wo) const;
  Color specular_fresnel(float cos_theta) const;
  Color glass_fresnel(float wo_dot_wm) const;
  Color reflection_fresnel(float wo_dot_wm, float glass_compensation = 1.0f) const;
  float glass_reflection_probability(float wo_dot_wm) const;
  float coat_fresnel(float cos_theta) const;
  Color evaluate(const Vec3& wo, const Vec3& wi, const Outgoing& o) const;
  Color evaluate_transmission(const Vec3& wo, const Vec3& wi) const;
  float density(const Vec3& wo, const Vec3& wi, const Outgoing& o) const;
  float transmission_density(const Vec3& wo, const Vec3& wi, float compensation) const;
  std::optional<Vec3> sample_direction(Lobe lobe, const Vec3& wo, float u_lobe, Sample2D u) const;
  std::optional<BsdfSample> sample_delta(Lobe lobe, const Vec3& wo, const Outgoing& o) const;
  std::optional<BsdfSample> sample_subsurface(const Vec3& wo, const Outgoing& o) const;

  Color base_color_;
  float metalness_, transmission_;
  float subsurface_;
  float eta_;  // n_inside / n_outside
  // The transmissive part is rough glass: one lobe samples its reflection and refraction both.
  bool rough_glass_ = false;
  GgxDistribution ggx_;
  Color specular_f0_;
  float specular_f90_;
  Color diffuse_normalization_;  // 1 / (1 − E_avg) of the specular layer, per channel; 0 where E_avg = 1
  float coat_weight_;
  GgxDistribution coat_ggx_;
  Color fuzz_color_;
  float fuzz_max_;
  SheenLobe fuzz_;
  ConductorBsdf metal_;
  std::array<bool, kLobeCount> active_;                // the lobe's weight is not zero for every wo
  std::array<bool, kLobeCount> sampled_with_density_;  // active and not a delta lobe
};

struct PrincipledSurface;  // scene/principled_material.h

// As render/bsdf/bsdf_from.h asks of every kind.
Vec3 bsdf_from(const PrincipledSurface& model, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);
// Only where its parameters (a metallic-roughness texture's included) leave the Lambert base
// alone, not wherever it is hit.
inline bool makes_lambert_bsdf(const PrincipledSurface&) { return false; }

}  // namespace rtpro
