#include "hair_bsdf.h"

#include "rtpro/core/math_constants.h"
#include "rtpro/scene/hair_absorption.h"
#include "rtpro/scene/hair_material.h"
#include "shading_frame.h"
#include "surface_bsdf.h"
#include "texture.h"

#include <algorithm>

namespace rtpro {

HairBsdf::HairBsdf(const Fibre& fibre, float axis_x, float axis_y, float offset)
    : axis_x_(axis_x), axis_y_(axis_y), offset_(offset), eta_(fibre.eta), sigma_a_(fibre.sigma_a) {
  set_roughness(fibre.beta_m, fibre.beta_n);
  const float alpha = fibre.alpha_degrees * (kPi / 180.0f);
  const std::array<float, kHairLobes> shifts{-2.0f * alpha, alpha, 4.0f * alpha, 0.0f};
  for (int p = 0; p < kHairLobes; ++p) {
    shift_sin_[p] = std::sin(shifts[p]);
    shift_cos_[p] = std::cos(shifts[p]);
  }
}

void HairBsdf::set_roughness(float beta_m, float beta_n) {
  beta_m_ = beta_m;
  beta_n_ = beta_n;
  v_ = longitudinal_variances(beta_m);
  s_ = azimuthal_scale(beta_n);
}

void HairBsdf::roughen_to(float min_alpha) {
  if (beta_m_ < min_alpha || beta_n_ < min_alpha)
    set_roughness(std::max(beta_m_, min_alpha), std::max(beta_n_, min_alpha));
}

HairBsdf::Outgoing HairBsdf::outgoing(const Vec3& w) const {
  Outgoing o;
  o.sin_o = std::clamp(w.x, -1.0f, 1.0f);
  o.cos_o = std::sqrt(std::max(0.0f, 1.0f - o.sin_o * o.sin_o));
  o.phi_o = std::atan2(w.z, w.y);
  float h = offset_;
  if (std::isnan(h)) h = o.cos_o > 0.0f ? std::clamp(-w.y / o.cos_o, -1.0f, 1.0f) : 0.0f;
  o.gamma_o = std::asin(h);
  // Inside, the ray runs at θt to the normal plane and its projection at offset angle γt, by
  // Bravais' index η' for the projected direction.
  const float sin_t = o.sin_o / eta_;
  const float cos_t = std::sqrt(std::max(0.0f, 1.0f - sin_t * sin_t));
  const float eta_projected =
      o.cos_o > 0.0f ? std::sqrt(std::max(0.0f, eta_ * eta_ - o.sin_o * o.sin_o)) / o.cos_o : eta_;
  const float sin_gamma_t = std::clamp(h / eta_projected, -1.0f, 1.0f);
  const float cos_gamma_t = std::sqrt(std::max(0.0f, 1.0f - sin_gamma_t * sin_gamma_t));
  o.gamma_t = std::asin(sin_gamma_t);
  // One crossing is 2 cos γt / cos θt radii long.
  const float crossing = 2.0f * cos_gamma_t / cos_t;
  const Color transmittance{std::exp(-sigma_a_.x * crossing), std::exp(-sigma_a_.y * crossing),
                            std::exp(-sigma_a_.z * crossing)};
  o.a = hair_attenuation(o.cos_o, eta_, h, transmittance);
  float total = 0.0f;
  for (const Color& a : o.a) total += channel_mean(a);
  for (int p = 0; p < kHairLobes; ++p) o.a_choice[p] = total > 0.0f ? channel_mean(o.a[p]) / total : 0.0f;
  return o;
}

void HairBsdf::tilted(const Outgoing& o, int p, float& sin_o, float& cos_o) const {
  sin_o = o.sin_o * shift_cos_[p] + o.cos_o * shift_sin_[p];
  // A tilt past the pole folds back: θ'o stays within [−π/2, π/2].
  cos_o = std::fabs(o.cos_o * shift_cos_[p] - o.sin_o * shift_sin_[p]);
}

std::array<float, kHairLobes> HairBsdf::lobes(const Outgoing& o, const Vec3& wi) const {
  const float sin_i = std::clamp(wi.x, -1.0f, 1.0f);
  const float cos_i = std::sqrt(std::max(0.0f, 1.0f - sin_i * sin_i));
  const float dphi = std::atan2(wi.z, wi.y) - o.phi_o;
  std::array<float, kHairLobes> m;
  for (int p = 0; p < kHairLobes; ++p) {
    float sin_o, cos_o;
    tilted(o, p, sin_o, cos_o);
    const float azimuthal = p < kHairLobes - 1 ? azimuthal_scattering(dphi, p, s_, o.gamma_o, o.gamma_t)
                                               : 0.5f * kInvPi;  // the residual: uniform in φ
    m[p] = longitudinal_scattering(cos_i, cos_o, sin_i, sin_o, v_[p]) * azimuthal;
  }
  return m;
}

Color HairBsdf::eval(const Vec3& wo, const Vec3& wi) const {
  if (wi.z == 0.0f) return Color(0.0f);
  const Outgoing o = outgoing(to_fibre(wo));
  const std::array<float, kHairLobes> m = lobes(o, to_fibre(wi));
  Color f(0.0f);
  for (int p = 0; p < kHairLobes; ++p) f += o.a[p] * m[p];
  return f / std::fabs(wi.z);
}

float HairBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  const Outgoing o = outgoing(to_fibre(wo));
  const std::array<float, kHairLobes> m = lobes(o, to_fibre(wi));
  float density = 0.0f;
  for (int p = 0; p < kHairLobes; ++p) density += o.a_choice[p] * m[p];
  return density;
}

std::optional<BsdfSample> HairBsdf::sample(const Vec3& wo, float u_lobe, Sample2D u) const {
  const Outgoing o = outgoing(to_fibre(wo));
  // The lobe, and what is left of u_lobe rescaled to [0, 1) for its azimuth; lobes that carry
  // nothing are never picked.
  int last = kHairLobes - 1;
  while (last >= 0 && !(o.a_choice[last] > 0.0f)) --last;
  if (last < 0) return std::nullopt;
  int p = 0;
  float u_azimuth = u_lobe;
  while (p < last && u_azimuth >= o.a_choice[p]) u_azimuth -= o.a_choice[p++];
  u_azimuth = std::min(u_azimuth / o.a_choice[p], kOneMinusEpsilon);

  // θi about the lobe's specular cone (θi = −θ'o), a cone of angle θ around it at azimuth 2πu.y.
  float sin_o, cos_o;
  tilted(o, p, sin_o, cos_o);
  const float cos_cone = sample_longitudinal_cosine(u.x, v_[p]);
  const float sin_cone = std::sqrt(std::max(0.0f, 1.0f - cos_cone * cos_cone));
  const float sin_i = std::clamp(-cos_cone * sin_o + sin_cone * std::cos(2.0f * kPi * u.y) * cos_o, -1.0f, 1.0f);
  const float cos_i = std::sqrt(std::max(0.0f, 1.0f - sin_i * sin_i));
  const float dphi = p < kHairLobes - 1 ? exit_azimuth(p, o.gamma_o, o.gamma_t) + sample_trimmed_logistic(u_azimuth, s_)
                                        : 2.0f * kPi * u_azimuth;
  const float phi_i = o.phi_o + dphi;
  const Vec3 wi_fibre{sin_i, cos_i * std::cos(phi_i), cos_i * std::sin(phi_i)};
  const Vec3 wi = from_fibre(wi_fibre);
  if (wi.z == 0.0f) return std::nullopt;

  const std::array<float, kHairLobes> m = lobes(o, wi_fibre);
  Color f(0.0f);
  float density = 0.0f;
  for (int q = 0; q < kHairLobes; ++q) {
    f += o.a[q] * m[q];
    density += o.a_choice[q] * m[q];
  }
  if (!(density > 0.0f)) return std::nullopt;
  return BsdfSample{f / std::fabs(wi.z),
                    wi,
                    density,
                    false,
                    wo.z * wi.z < 0.0f,
                    p == 0 ? BsdfLobe::kGlossy : BsdfLobe::kTransmission};
}

Color HairBsdf::attenuation(const Vec3& wo) const {
  const Outgoing o = outgoing(to_fibre(wo));
  Color sum(0.0f);
  for (const Color& a : o.a) sum += a;
  return sum;
}

Vec3 bsdf_from(const HairSurface& hair, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out) {
  const Vec3& n = point.shading_normal;
  // The frame material_bsdf builds around the normal returned (hair needs no outward one).
  const Vec3 tangent = ShadingFrame::from_normal(n).to_local(point.tangent);
  const float across = std::hypot(tangent.x, tangent.y);
  const bool has_axis = across > 1e-4f * length(point.tangent) && std::isfinite(1.0f / across);
  const float axis_x = has_axis ? tangent.x / across : 1.0f;
  const float axis_y = has_axis ? tangent.y / across : 0.0f;
  Color color = hair.color, sigma_a = hair.sigma_a;
  if (hair.sigma_a_from_color) {
    color = evaluate(base_color, point, textures);
    sigma_a = hair_sigma_a_from_color(color, hair.beta_n);
  }
  const float offset = point.fiber_offset != 0.0f ? point.fiber_offset : HairBsdf::kOffsetFromWo;
  out.bsdf = HairBsdf({hair.ior, sigma_a, hair.beta_m, hair.beta_n, hair.alpha_degrees}, axis_x, axis_y, offset);
  out.albedo = color;
  return n;
}

}  // namespace rtpro
