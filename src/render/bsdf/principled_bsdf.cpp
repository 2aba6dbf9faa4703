#include "principled_bsdf.h"

#include "rtpro/scene/principled_material.h"
#include "surface_bsdf.h"
#include "normal_map.h"
#include "texture.h"
#include "rtpro/core/math_constants.h"
#include "dielectric.h"
#include "dielectric_albedo.h"
#include "rough_glass_sampling.h"
#include "transmission_geometry.h"
#include "specular_albedo.h"

#include <algorithm>
#include <cmath>

namespace rtpro {
namespace {

constexpr float kCoatF0 = 0.04f;  // KHR_materials_clearcoat: ior 1.5
// Every lobe that can contribute keeps at least this share of the samples: the albedo estimates
// behind the choice can be near zero where f is not (a rough transmission beyond the critical
// angle, a smooth sheen seen from above), and a lobe never sampled would leave its light to the
// light sampler alone.
constexpr float kMinLobeShare = 0.02f;

float clamp01(float x) { return std::clamp(x, 0.0f, 1.0f); }
Color clamp01(const Color& c) { return {clamp01(c.x), clamp01(c.y), clamp01(c.z)}; }

}  // namespace

PrincipledBsdf::PrincipledBsdf(const PrincipledParameters& p)
    : base_color_(clamp01(p.base_color)), metalness_(clamp01(p.metalness)),
      transmission_(clamp01(p.transmission_weight)), subsurface_(clamp01(p.subsurface_weight)),
      eta_(std::max(1.0f, p.ior)), ggx_{roughness_to_alpha(clamp01(p.roughness))},
      specular_f90_(clamp01(p.specular_weight)),
      coat_weight_(clamp01(p.coat_weight)), coat_ggx_{roughness_to_alpha(clamp01(p.coat_roughness))},
      fuzz_color_(clamp01(p.fuzz_color)), fuzz_max_(max_component(fuzz_color_)), fuzz_(p.fuzz_roughness),
      metal_(ConductorBsdf::from_f0(base_color_, ggx_.alpha, metalness_ > 0.0f)) {
  // KHR_materials_specular clamps the tinted F0 before applying the weight.
  const float reflectance = ((eta_ - 1.0f) / (eta_ + 1.0f)) * ((eta_ - 1.0f) / (eta_ + 1.0f));
  specular_f0_ = min(max(p.specular_color, Color(0.0f)) * reflectance, Color(1.0f)) * specular_f90_;
  normalize_diffuse();

  const bool dielectric = metalness_ < 1.0f;
  const bool reflects = has_specular_layer();
  const bool tinted = max_component(base_color_) > 0.0f;
  rough_glass_ = dielectric && transmission_ > 0.0f && !lobe_is_delta(kTransmission);
  active_[kCoat] = coat_weight_ > 0.0f;
  active_[kFuzz] = fuzz_max_ > 0.0f;
  // The opaque part's reflection, and the glass part's where the glass lobe does not sample its
  // own: from inside, total internal reflection happens whatever the specular weight.
  active_[kSpecular] = dielectric && ((reflects && transmission_ < 1.0f) || (transmission_ > 0.0f && !rough_glass_));
  active_[kDiffuse] = dielectric && transmission_ < 1.0f && tinted && subsurface_ < 1.0f;
  active_[kSubsurface] = dielectric && transmission_ < 1.0f && tinted && subsurface_ > 0.0f;
  // Rough glass reflects even when black (total internal reflection); smooth glass only refracts here.
  active_[kTransmission] = dielectric && transmission_ > 0.0f && (tinted || rough_glass_);
  active_[kMetal] = metalness_ > 0.0f;
  find_sampled_with_density();
}

// Without a specular layer (specular weight 0) its albedo is 0 exactly: the tables are not read,
// nor built by a scene that needs them nowhere else.
bool PrincipledBsdf::has_specular_layer() const { return max_component(specular_f0_) > 0.0f || specular_f90_ > 0.0f; }

void PrincipledBsdf::normalize_diffuse() {
  const Color average =
      has_specular_layer() ? ggx_schlick_average_albedo(ggx_.alpha)(specular_f0_, specular_f90_) : Color(0.0f);
  for (int c = 0; c < 3; ++c) diffuse_normalization_[c] = average[c] < 1.0f ? 1.0f / (1.0f - average[c]) : 0.0f;
}

bool PrincipledBsdf::lobe_is_delta(Lobe lobe) const {
  switch (lobe) {
    case kCoat: return coat_ggx_.effectively_smooth();
    case kFuzz:
    case kDiffuse:
    case kSubsurface: return false;
    case kSpecular:
    case kMetal: return ggx_.effectively_smooth();
    // η = 1 bends nothing: the refraction is straight through, whatever α says.
    case kTransmission: return ggx_.effectively_smooth() || eta_ == 1.0f;
    case kLobeCount: break;
  }
  return false;  // unreachable: the switch covers every lobe
}

bool PrincipledBsdf::is_delta() const {
  bool any = false;
  for (int k = 0; k < kLobeCount; ++k) {
    if (!active_[k]) continue;
    if (!lobe_is_delta(static_cast<Lobe>(k))) return false;
    any = true;
  }
  return any;
}

Color PrincipledBsdf::specular_fresnel(float cos_theta) const {
  return specular_f0_ + (Color(specular_f90_) - specular_f0_) * schlick_weight(cos_theta);
}

// Schlick's approximation depends on the angle on the outside: seen from inside, the cosine is
// that of the refracted direction, and beyond the critical angle everything reflects. So a facet
// reflects as much from either side, and nothing leaks out where no light can.
Color PrincipledBsdf::glass_fresnel(float wo_dot_wm) const {
  if (wo_dot_wm >= 0.0f) return specular_fresnel(wo_dot_wm);
  const float sin2_t = (1.0f - wo_dot_wm * wo_dot_wm) * eta_ * eta_;
  if (sin2_t >= 1.0f) return Color(1.0f);
  return specular_fresnel(std::sqrt(1.0f - sin2_t));
}

// The opaque part reflects alike on either side; the transmissive part as glass does, times its
// energy compensation.
Color PrincipledBsdf::reflection_fresnel(float wo_dot_wm, float glass_compensation) const {
  const Color opaque = specular_fresnel(std::fabs(wo_dot_wm));
  if (transmission_ == 0.0f) return opaque;
  return opaque * (1.0f - transmission_) + glass_fresnel(wo_dot_wm) * (transmission_ * glass_compensation);
}

// The rough glass lobe reflects at a facet with this probability and refracts otherwise: the
// untinted Schlick F its compensation table integrates, so what the lobe keeps is distributed as
// its compensated f·|cos θi| for the default specular colour and weight.
float PrincipledBsdf::glass_reflection_probability(float wo_dot_wm) const {
  return schlick_glass_fresnel(std::fabs(wo_dot_wm), wo_dot_wm >= 0.0f ? eta_ : 1.0f / eta_);
}

float PrincipledBsdf::coat_fresnel(float cos_theta) const {
  return kCoatF0 + (1.0f - kCoatF0) * schlick_weight(cos_theta);
}

PrincipledBsdf::Outgoing PrincipledBsdf::outgoing(const Vec3& wo) const {
  Outgoing o{};
  o.cos_o = abs_cos_theta(wo);
  if ((active_[kSpecular] || active_[kDiffuse] || active_[kSubsurface]) && has_specular_layer())
    o.specular_albedo = ggx_schlick_albedo(o.cos_o, ggx_.alpha)(specular_f0_, specular_f90_);
  const float coat_albedo = active_[kCoat] ? ggx_schlick_albedo(o.cos_o, coat_ggx_.alpha)(kCoatF0, 1.0f) : 0.0f;
  const float fuzz_albedo = active_[kFuzz] ? fuzz_.albedo(o.cos_o) : 0.0f;
  o.below_coat = 1.0f - coat_weight_ * coat_albedo;
  o.below_fuzz = o.below_coat * std::max(0.0f, 1.0f - fuzz_max_ * fuzz_albedo);
  if (rough_glass_) {
    // DielectricBsdf's compensation, for this glass's Schlick F with F0 from the ior: exact for
    // the default specular colour and weight, approximate for others.
    const float albedo = rough_dielectric_albedo(o.cos_o, ggx_.alpha, relative_eta(wo, eta_), GlassFresnel::kSchlick);
    o.glass_compensation = albedo > 0.0f ? 1.0f / albedo : 1.0f;
  }

  // Estimates of each lobe's albedo at wo; exact for the delta lobes, whose weight is a Fresnel
  // factor at wo.
  const float dielectric = o.below_fuzz * (1.0f - metalness_);
  // Seen from inside, the glass part reflects by its own Fresnel (total internal reflection).
  const Color glass_reflectance = wo.z > 0.0f || !active_[kTransmission] ? o.specular_albedo : glass_fresnel(wo.z);
  const Color glass_passed = base_color_ * (Color(1.0f) - glass_fresnel(wo.z));
  std::array<float, kLobeCount> estimate{};
  if (active_[kCoat]) estimate[kCoat] = coat_weight_ * coat_albedo;
  if (active_[kFuzz]) estimate[kFuzz] = o.below_coat * channel_mean(fuzz_color_) * fuzz_albedo;
  if (active_[kSpecular]) {
    const float glass = rough_glass_ ? 0.0f : transmission_ * channel_mean(glass_reflectance);
    estimate[kSpecular] = dielectric * ((1.0f - transmission_) * channel_mean(o.specular_albedo) + glass);
  }
  const float base =
      dielectric * (1.0f - transmission_) * channel_mean(base_color_ * (Color(1.0f) - o.specular_albedo));
  if (active_[kDiffuse]) estimate[kDiffuse] = base * (1.0f - subsurface_);
  if (active_[kSubsurface]) estimate[kSubsurface] = base * subsurface_;
  if (active_[kTransmission]) {
    const float reflected = rough_glass_ ? channel_mean(glass_reflectance) : 0.0f;
    estimate[kTransmission] = dielectric * transmission_ * (reflected + channel_mean(glass_passed));
  }
  if (active_[kMetal]) estimate[kMetal] = o.below_fuzz * metalness_ * channel_mean(metal_.fresnel(o.cos_o));

  float total = 0.0f;
  for (float e : estimate) total += e;
  if (total <= 0.0f) return o;  // nothing reflects or transmits: every probability stays 0
  float floored_total = 0.0f;
  for (int k = 0; k < kLobeCount; ++k) {
    if (sampled_with_density_[k]) estimate[k] = std::max(estimate[k], kMinLobeShare * total);
    floored_total += estimate[k];
  }
  for (int k = 0; k < kLobeCount; ++k) o.probability[k] = estimate[k] / floored_total;
  return o;
}

Color PrincipledBsdf::evaluate_transmission(const Vec3& wo, const Vec3& wi) const {
  const std::optional<TransmissionGeometry> t = transmission_geometry(wo, wi, eta_);
  if (!t) return Color(0.0f);
  const Color passed = Color(1.0f) - glass_fresnel(t->wo_dot_wm);
  // Walter et al.'s transmission term with the radiance scale 1/etap², as in DielectricBsdf.
  const float walter = ggx_.d(t->wm) * ggx_.g(wo, wi) *
                       std::fabs(t->wi_dot_wm * t->wo_dot_wm / (wi.z * wo.z * t->denom)) / (t->etap * t->etap);
  return base_color_ * passed * (transmission_ * walter);
}

float PrincipledBsdf::transmission_density(const Vec3& wo, const Vec3& wi, float compensation) const {
  const std::optional<TransmissionGeometry> t = transmission_geometry(wo, wi, eta_);
  if (!t) return 0.0f;
  const float refracted = 1.0f - glass_reflection_probability(t->wo_dot_wm);
  return ggx_.visible_normal_pdf(wo, t->wm) * std::fabs(t->wi_dot_wm) / t->denom * refracted *
         kept_fraction(ggx_, wo, wi) * compensation;
}

Color PrincipledBsdf::evaluate(const Vec3& wo, const Vec3& wi, const Outgoing& o) const {
  if (wo.z == 0.0f || wi.z == 0.0f) return Color(0.0f);
  if (!same_hemisphere(wo, wi)) {
    if (!sampled_with_density_[kTransmission]) return Color(0.0f);
    return evaluate_transmission(wo, wi) * (o.below_fuzz * (1.0f - metalness_) * o.glass_compensation);
  }
  const std::optional<Vec3> wm = reflection_normal(wo, wi);
  if (!wm) return Color(0.0f);
  Color f(0.0f);
  if (sampled_with_density_[kCoat]) {
    f += Color(coat_weight_ * microfacet_reflection(coat_ggx_, wo, wi, *wm) * coat_fresnel(std::fabs(dot(wo, *wm))));
  }
  if (active_[kFuzz]) f += fuzz_color_ * (o.below_coat * fuzz_.eval(wo, wi));

  Color material(0.0f);
  if (metalness_ < 1.0f) {
    Color dielectric(0.0f);
    if (sampled_with_density_[kSpecular] || rough_glass_) {
      dielectric += reflection_fresnel(dot(wo, *wm), o.glass_compensation) * microfacet_reflection(ggx_, wo, wi, *wm);
    }
    if (active_[kDiffuse]) {
      const Color albedo_i = has_specular_layer()
                                 ? ggx_schlick_albedo(abs_cos_theta(wi), ggx_.alpha)(specular_f0_, specular_f90_)
                                 : Color(0.0f);
      Color lambert;
      for (int c = 0; c < 3; ++c) {
        const float passed = (1.0f - o.specular_albedo[c]) * (1.0f - albedo_i[c]);
        lambert[c] = base_color_[c] * (std::max(0.0f, passed) * diffuse_normalization_[c] * kInvPi);
      }
      dielectric += lambert * ((1.0f - transmission_) * (1.0f - subsurface_));
    }
    material += dielectric * (1.0f - metalness_);
  }
  if (sampled_with_density_[kMetal]) material += metal_.eval(wo, wi) * metalness_;
  return f + material * o.below_fuzz;
}

float PrincipledBsdf::density(const Vec3& wo, const Vec3& wi, const Outgoing& o) const {
  if (wo.z == 0.0f || wi.z == 0.0f) return 0.0f;
  const auto weight = [&](Lobe lobe) { return sampled_with_density_[lobe] ? o.probability[lobe] : 0.0f; };
  if (!same_hemisphere(wo, wi)) {
    const float p = weight(kTransmission);
    return p > 0.0f ? p * transmission_density(wo, wi, o.glass_compensation) : 0.0f;
  }
  const std::optional<Vec3> wm = reflection_normal(wo, wi);
  if (!wm) return 0.0f;
  float pdf = 0.0f;
  if (const float p = weight(kCoat); p > 0.0f) pdf += p * reflection_density(coat_ggx_, wo, *wm);
  if (const float p = weight(kFuzz); p > 0.0f) pdf += p * (0.5f * kInvPi);  // uniform over the hemisphere
  if (const float p = weight(kSpecular); p > 0.0f) pdf += p * reflection_density(ggx_, wo, *wm);
  if (const float p = rough_glass_ ? weight(kTransmission) : 0.0f; p > 0.0f)
    pdf += p * reflection_density(ggx_, wo, *wm) * glass_reflection_probability(dot(wo, *wm)) *
           kept_fraction(ggx_, wo, wi) * o.glass_compensation;
  if (const float p = weight(kDiffuse); p > 0.0f) pdf += p * cosine_hemisphere_pdf(abs_cos_theta(wi));
  if (const float p = weight(kMetal); p > 0.0f) pdf += p * metal_.pdf(wo, wi);
  return pdf;
}

Color PrincipledBsdf::eval(const Vec3& wo, const Vec3& wi) const { return evaluate(wo, wi, outgoing(wo)); }

float PrincipledBsdf::pdf(const Vec3& wo, const Vec3& wi) const { return density(wo, wi, outgoing(wo)); }

std::optional<Vec3> PrincipledBsdf::sample_direction(Lobe lobe, const Vec3& wo, float u_lobe, Sample2D u) const {
  switch (lobe) {
    case kCoat: return sample_reflection(coat_ggx_, wo, u);
    case kSpecular: return sample_reflection(ggx_, wo, u);
    case kFuzz: {
      // Uniform over the hemisphere: the sheen lives at grazing angles, where cosine sampling is
      // thinnest (Estevez and Kulla's advice).
      const float z = u.x;
      const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
      const float phi = 2.0f * kPi * u.y;
      return Vec3{r * std::cos(phi), r * std::sin(phi), wo.z < 0.0f ? -z : z};
    }
    case kDiffuse: {
      Vec3 wi = sample_cosine_hemisphere(u);
      if (wo.z < 0.0f) wi.z = -wi.z;
      return wi;
    }
    case kTransmission:
      return sample_rough_glass(ggx_, wo, eta_, u_lobe, u, true,
                                [&](float wo_dot_wm) { return glass_reflection_probability(wo_dot_wm); });
    case kMetal: {
      const std::optional<BsdfSample> s = metal_.sample(wo, u_lobe, u);
      if (!s) return std::nullopt;
      return s->wi;
    }
    case kSubsurface:
    case kLobeCount: break;  // the subsurface lobe has no direction to sample here
  }
  return std::nullopt;  // unreachable: the switch covers every lobe
}

// A mirror direction gathers every smooth reflecting lobe (coat, specular, metal) at once: one
// sample carries their summed weight with their summed probability, rather than one lobe's weight
// over its own share.
std::optional<BsdfSample> PrincipledBsdf::sample_delta(Lobe lobe, const Vec3& wo, const Outgoing& o) const {
  if (lobe == kTransmission) {
    const std::optional<Vec3> wi = refract_through(wo, Vec3{0.0f, 0.0f, 1.0f}, eta_);
    if (!wi || wi->z * wo.z >= 0.0f) return std::nullopt;
    const float etap = relative_eta(wo, eta_);
    const Color weight = base_color_ * (Color(1.0f) - glass_fresnel(wo.z)) *
                         (o.below_fuzz * (1.0f - metalness_) * transmission_ / (etap * etap));
    return BsdfSample{weight / abs_cos_theta(*wi), *wi, o.probability[kTransmission], true, true,
                      BsdfLobe::kTransmission,     etap};
  }
  Color weight(0.0f);
  float probability = 0.0f;
  if (active_[kCoat] && lobe_is_delta(kCoat)) {
    weight += Color(coat_weight_ * coat_fresnel(o.cos_o));
    probability += o.probability[kCoat];
  }
  if (active_[kSpecular] && lobe_is_delta(kSpecular)) {
    weight += reflection_fresnel(wo.z) * (o.below_fuzz * (1.0f - metalness_));
    probability += o.probability[kSpecular];
  }
  if (active_[kMetal] && lobe_is_delta(kMetal)) {
    weight += metal_.fresnel(o.cos_o) * (o.below_fuzz * metalness_);
    probability += o.probability[kMetal];
  }
  const Vec3 wi{-wo.x, -wo.y, wo.z};
  return BsdfSample{weight / o.cos_o, wi, probability, true, false, BsdfLobe::kGlossy};
}

// What enters under the surface: the Lambert lobe's energy without its colour, the path pointed
// along the inward normal, a choice of lobe rather than a direction (pdf its probability).
std::optional<BsdfSample> PrincipledBsdf::sample_subsurface(const Vec3& wo, const Outgoing& o) const {
  const Color weight =
      (Color(1.0f) - o.specular_albedo) * (o.below_fuzz * (1.0f - metalness_) * (1.0f - transmission_) * subsurface_);
  const Vec3 inward{0.0f, 0.0f, wo.z > 0.0f ? -1.0f : 1.0f};
  return BsdfSample{weight, inward, o.probability[kSubsurface], true, true, BsdfLobe::kSubsurface};
}

std::optional<BsdfSample> PrincipledBsdf::sample(const Vec3& wo, float u_lobe, Sample2D u) const {
  if (wo.z == 0.0f) return std::nullopt;
  const Outgoing o = outgoing(wo);
  // The lobe whose share of [0, 1) holds u_lobe; u_lobe rescaled within that share is fresh again.
  int chosen = -1;
  float share_start = 0.0f, next_start = 0.0f;
  for (int k = 0; k < kLobeCount && (chosen < 0 || u_lobe >= next_start); ++k) {
    if (o.probability[k] <= 0.0f) continue;
    chosen = k;
    share_start = next_start;
    next_start += o.probability[k];
  }
  if (chosen < 0) return std::nullopt;
  const Lobe lobe = static_cast<Lobe>(chosen);
  const float u_within = std::clamp((u_lobe - share_start) / o.probability[lobe], 0.0f, kOneMinusEpsilon);
  if (lobe == kSubsurface) return sample_subsurface(wo, o);
  if (lobe_is_delta(lobe)) return sample_delta(lobe, wo, o);

  const std::optional<Vec3> wi = sample_direction(lobe, wo, u_within, u);
  if (!wi || wi->z == 0.0f) return std::nullopt;
  // f and pdf of the whole mixture, as eval() and pdf() compute them, so MIS weights match.
  const float pdf = density(wo, *wi, o);
  if (pdf == 0.0f) return std::nullopt;
  const bool transmitted = !same_hemisphere(wo, *wi);
  return BsdfSample{
      evaluate(wo, *wi, o), *wi, pdf, false, transmitted, lobe_kind(lobe), transmitted ? relative_eta(wo, eta_) : 1.0f};
}

Vec3 bsdf_from(const PrincipledSurface& p, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out) {
  PrincipledParameters parameters;
  parameters.base_color = evaluate(base_color, point, textures);
  parameters.metalness = p.metalness;
  parameters.roughness = p.roughness;
  parameters.ior = p.ior;
  parameters.specular_weight = p.specular_weight;
  parameters.specular_color = p.specular_color;
  parameters.transmission_weight = p.transmission_weight;
  parameters.coat_weight = p.coat_weight;
  parameters.coat_roughness = p.coat_roughness;
  parameters.fuzz_color = p.fuzz_color;
  parameters.fuzz_roughness = p.fuzz_roughness;
  parameters.subsurface_weight = p.subsurface;
  if (p.metallic_roughness) {
    const Color texel = evaluate(*p.metallic_roughness, point.tex_u, point.tex_v, textures);
    parameters.roughness = texel.y;
    parameters.metalness = texel.z;
  }
  const Vec3 normal = p.normal_map ? mapped_normal(*p.normal_map, point, textures) : point.shading_normal;
  // KHR_materials_specular's specularFactor 0 on a non-metal without other layers is the pure
  // Lambert base, by the extension's definition: the same f and pdf from the cheaper kind.
  if (p.specular_weight == 0.0f && parameters.metalness == 0.0f && p.transmission_weight == 0.0f &&
      p.coat_weight == 0.0f && max_component(p.fuzz_color) == 0.0f && p.subsurface == 0.0f)
    return lambert_surface(parameters.base_color, normal, out);
  out.bsdf = PrincipledBsdf(parameters);
  out.albedo = parameters.base_color;
  return normal;
}

}  // namespace rtpro
