#include "dielectric_bsdf.h"

#include "rtpro/scene/dielectric_material.h"
#include "surface_bsdf.h"
#include "texture.h"
#include "dielectric.h"
#include "dielectric_albedo.h"
#include "rough_glass_sampling.h"

#include <cmath>

namespace rtpro {
namespace {

// Fresnel reflectance for a direction on either side of a facet with normal n pointing outside:
// cos_theta < 0 means the light arrives from inside, where the index ratio is inverted.
float fresnel_either_side(float cos_theta, float eta) {
  return cos_theta >= 0.0f ? fresnel_dielectric(cos_theta, eta) : fresnel_dielectric(-cos_theta, 1.0f / eta);
}

struct Evaluation {
  Color f;
  float pdf;
};

// f of single scattering and the density of choosing a visible normal and then reflection or
// refraction by the facet's F; with `compensation` = 1/E(μo), f times it and the density that of
// keeping only the attempts accepted with probability G(wo, wi)/G1(wo): pdf·G/G1/E.
Evaluation evaluate_rough(const Vec3& wo, const Vec3& wi, float eta, const GgxDistribution& ggx,
                          std::optional<float> compensation) {
  const Evaluation nothing{Color(0.0f), 0.0f};
  const float cos_o = cos_theta(wo);
  const float cos_i = cos_theta(wi);
  if (cos_o == 0.0f || cos_i == 0.0f) return nothing;
  const bool reflected = cos_o * cos_i > 0.0f;
  const float etap = reflected ? 1.0f : relative_eta(wo, eta);
  // The generalized half vector: the facet normal that turns wo into wi, by reflection or by Snell.
  const Vec3 half = wi * etap + wo;
  const float half_length2 = dot(half, half);
  if (half_length2 == 0.0f) return nothing;
  Vec3 wm = half / std::sqrt(half_length2);
  if (wm.z < 0.0f) wm = -wm;
  // A facet seen from behind by either direction cannot connect them.
  if (dot(wm, wi) * cos_i < 0.0f || dot(wm, wo) * cos_o < 0.0f) return nothing;

  const float r = fresnel_either_side(dot(wo, wm), eta);
  const float t = 1.0f - r;
  const float g = ggx.g(wo, wi);
  const float scale = compensation.value_or(1.0f);
  const float d_g = ggx.d(wm) * g * scale;
  const float visible = compensation ? ggx.visible_normal_pdf(wo, wm) * kept_fraction(ggx, wo, wi) * scale
                                     : ggx.visible_normal_pdf(wo, wm);
  if (reflected) {
    return {Color(d_g * r / std::fabs(4.0f * cos_i * cos_o)), visible / (4.0f * std::fabs(dot(wo, wm))) * r};
  }
  const float wi_dot_wm = dot(wi, wm);
  const float wo_dot_wm = dot(wo, wm);
  const float denom = (wi_dot_wm + wo_dot_wm / etap) * (wi_dot_wm + wo_dot_wm / etap);
  if (denom == 0.0f) return nothing;
  // Walter et al.'s transmission term, with the radiance scale 1/etap².
  const float f = d_g * t * std::fabs(wi_dot_wm * wo_dot_wm / (cos_i * cos_o * denom)) / (etap * etap);
  const float dwm_dwi = std::fabs(wi_dot_wm) / denom;
  return {Color(f), visible * dwm_dwi * t};
}

std::optional<BsdfSample> sample_smooth(const Vec3& wo, float eta, float u_lobe) {
  // η = 1 exactly: Fresnel's formula leaves a rounding residue, and u_lobe = 0 would reflect.
  const float r = eta == 1.0f ? 0.0f : fresnel_either_side(cos_theta(wo), eta);
  if (u_lobe < r) {
    const Vec3 wi{-wo.x, -wo.y, wo.z};
    return BsdfSample{Color(r / abs_cos_theta(wi)), wi, r, true, false, BsdfLobe::kGlossy};
  }
  const std::optional<Vec3> wi = refract_through(wo, Vec3{0.0f, 0.0f, 1.0f}, eta);
  if (!wi || wi->z == 0.0f) return std::nullopt;
  const float t = 1.0f - r;
  const float etap = relative_eta(wo, eta);
  return BsdfSample{Color(t / abs_cos_theta(*wi) / (etap * etap)), *wi, t, true, true, BsdfLobe::kTransmission, etap};
}

}  // namespace

std::optional<float> DielectricBsdf::compensation(const Vec3& wo) const {
  if (!energy_compensation) return std::nullopt;
  const float albedo = rough_dielectric_albedo(abs_cos_theta(wo), alpha, relative_eta(wo, eta));
  return albedo > 0.0f ? 1.0f / albedo : 1.0f;
}

Color DielectricBsdf::eval(const Vec3& wo, const Vec3& wi) const {
  if (is_delta()) return Color(0.0f);
  return evaluate_rough(wo, wi, eta, GgxDistribution{alpha}, compensation(wo)).f;
}

float DielectricBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  if (is_delta()) return 0.0f;
  return evaluate_rough(wo, wi, eta, GgxDistribution{alpha}, compensation(wo)).pdf;
}

std::optional<BsdfSample> DielectricBsdf::sample(const Vec3& wo, float u_lobe, Sample2D u) const {
  if (wo.z == 0.0f) return std::nullopt;
  if (is_delta()) return sample_smooth(wo, eta, u_lobe);
  const GgxDistribution ggx{alpha};
  const std::optional<float> scale = compensation(wo);
  const std::optional<Vec3> wi = sample_rough_glass(
      ggx, wo, eta, u_lobe, u, scale.has_value(), [&](float wo_dot_wm) { return fresnel_either_side(wo_dot_wm, eta); });
  if (!wi) return std::nullopt;
  // f and pdf from wi alone, as eval() and pdf() compute them, so MIS weights match exactly.
  const Evaluation e = evaluate_rough(wo, *wi, eta, ggx, scale);
  if (e.pdf == 0.0f) return std::nullopt;
  const bool transmitted = wi->z * wo.z < 0.0f;
  if (!transmitted) return BsdfSample{e.f, *wi, e.pdf, false, false, BsdfLobe::kGlossy};
  return BsdfSample{e.f, *wi, e.pdf, false, true, BsdfLobe::kTransmission, relative_eta(wo, eta)};
}

Vec3 bsdf_from(const DielectricSurface& d, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out) {
  out.bsdf = DielectricBsdf{d.glass.ior, roughness_to_alpha(d.roughness)};
  out.albedo = evaluate(base_color, point, textures);
  return point.shading_normal;
}

}  // namespace rtpro
