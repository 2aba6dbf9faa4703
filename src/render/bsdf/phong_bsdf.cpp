#include "phong_bsdf.h"

#include "rtpro/core/math_constants.h"
#include "rtpro/scene/phong_material.h"
#include "surface_bsdf.h"
#include "texture.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

float phong_alpha(float shininess) { return std::sqrt(2.0f / (4.0f * std::max(shininess, 0.0f) + 2.0f)); }

float phong_highlight_albedo(float specular, float shininess) {
  return 2.0f * std::max(specular, 0.0f) / (std::max(shininess, 0.0f) + 2.0f);
}

PhongBsdf PhongBsdf::from_whitted(const Color& kd, float specular, float shininess, float reflectivity) {
  const float mirror = std::clamp(reflectivity, 0.0f, 1.0f);
  float highlight = std::min(phong_highlight_albedo(specular, shininess), 1.0f - mirror);
  const float alpha = phong_alpha(shininess);
  // A highlight narrower than anything an image resolves is a mirror (as ConductorBsdf's).
  float mirror_weight = mirror;
  if (alpha < kSmoothAlpha) {
    mirror_weight += highlight;
    highlight = 0.0f;
  }
  Color diffuse{std::clamp(kd.x, 0.0f, 1.0f), std::clamp(kd.y, 0.0f, 1.0f), std::clamp(kd.z, 0.0f, 1.0f)};
  const float room = std::max(0.0f, 1.0f - mirror_weight - highlight);
  if (max_component(diffuse) > room) diffuse = diffuse * (room / max_component(diffuse));
  return PhongBsdf(diffuse, highlight, alpha, mirror_weight);
}

PhongBsdf::PhongBsdf(const Color& diffuse, float highlight, float alpha, float mirror)
    : diffuse_(diffuse), highlight_(highlight), mirror_(mirror), ggx_{alpha} {
  const float d = (diffuse.x + diffuse.y + diffuse.z) / 3.0f, total = mirror + d + highlight;
  p_mirror_ = total > 0.0f ? mirror / total : 0.0f;
  p_diffuse_ = total > 0.0f ? d / total : 0.0f;
  p_highlight_ = total > 0.0f ? highlight / total : 0.0f;
}

PhongBsdf::Highlight PhongBsdf::highlight_at(const Vec3& wo, const Vec3& wi) const {
  if (highlight_ == 0.0f) return {0.0f, 0.0f};
  const Vec3 half = wo + wi;
  const float half_length2 = dot(half, half);
  if (half_length2 == 0.0f) return {0.0f, 0.0f};
  Vec3 wm = half / std::sqrt(half_length2);
  if (wm.z < 0.0f) wm = -wm;  // the facet normal faces out even when the surface is seen from behind
  const float wo_dot_wm = std::fabs(dot(wo, wm));
  const float f = highlight_ * ggx_.d(wm) * ggx_.g(wo, wi) / (4.0f * abs_cos_theta(wi) * abs_cos_theta(wo));
  // Reflection about wm doubles solid angles at the facet: dωm/dωi = 1 / (4 |wo·wm|).
  const float pdf = ggx_.visible_normal_pdf(wo, wm) / (4.0f * wo_dot_wm);
  return {f, pdf};
}

Color PhongBsdf::eval(const Vec3& wo, const Vec3& wi) const {
  if (!same_hemisphere(wo, wi)) return Color(0.0f);
  return diffuse_ * kInvPi + Color(highlight_at(wo, wi).f);
}

float PhongBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  if (!same_hemisphere(wo, wi)) return 0.0f;
  return p_diffuse_ * cosine_hemisphere_pdf(abs_cos_theta(wi)) + p_highlight_ * highlight_at(wo, wi).pdf;
}

std::optional<BsdfSample> PhongBsdf::sample(const Vec3& wo, float u_lobe, Sample2D u) const {
  if (wo.z == 0.0f || p_mirror_ + p_diffuse_ + p_highlight_ == 0.0f) return std::nullopt;
  if (u_lobe < p_mirror_) {
    const Vec3 wi{-wo.x, -wo.y, wo.z};
    return BsdfSample{Color(mirror_ / abs_cos_theta(wi)), wi, p_mirror_, true, false, BsdfLobe::kGlossy};
  }
  Vec3 wi;
  const bool diffuse = u_lobe < p_mirror_ + p_diffuse_;
  if (diffuse) {
    wi = sample_cosine_hemisphere(u);
    if (wo.z < 0.0f) wi.z = -wi.z;
  } else {
    wi = -reflect(wo, ggx_.sample_visible_normal(wo, u));
  }
  // Facets near the horizon reflect some directions into the surface: that light is lost.
  const float density = pdf(wo, wi);
  if (!(density > 0.0f)) return std::nullopt;
  return BsdfSample{eval(wo, wi), wi, density, false, false, diffuse ? BsdfLobe::kDiffuse : BsdfLobe::kGlossy};
}

namespace {

// Out of line, so that the Lambert case of bsdf_from stays small enough for material_bsdf to
// inline (it is most phong surfaces of a path-traced scene: 2.7% of a Cornell box's render).
[[gnu::noinline]] Vec3 glass_or_glossy_phong(const PhongSurface& phong, const Color& c, const SurfacePoint& point,
                                             SurfaceBsdf& out) {
  out.albedo = c;
  if (phong.glass) out.bsdf = DielectricBsdf{phong.glass->ior, 0.0f};
  else out.bsdf = PhongBsdf::from_whitted(c, phong.specular, phong.shininess, phong.reflectivity);
  return point.shading_normal;
}

}  // namespace

Vec3 bsdf_from(const PhongSurface& phong, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out) {
  const Color c = evaluate(base_color, point, textures);
  if (makes_lambert_bsdf(phong)) return lambert_surface(c, point.shading_normal, out);
  return glass_or_glossy_phong(phong, c, point, out);
}

bool makes_lambert_bsdf(const PhongSurface& phong) {
  return !phong.glass && !(phong.specular > 0.0f) && !(phong.reflectivity > 0.0f);
}

}  // namespace rtpro
