#include "conductor_bsdf.h"

#include "rtpro/scene/conductor_material.h"
#include "surface_bsdf.h"
#include "texture.h"
#include "rtpro/core/math_constants.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace rtpro {
namespace {

// F_avg of Schlick's F0 + (1 − F0)(1 − μ)⁵ in closed form: 2∫(1 − μ)⁵ μ dμ = 1/21.
Color schlick_average(const Color& f0) { return (f0 * 20.0f + Color(1.0f)) / 21.0f; }

// 2∫F(μ)μ dμ by composite Simpson: 32 intervals agree with 4096 to 1e-6 even for κ = 12.
Color integrate_complex_ior_average(const Color& eta, const Color& k) {
  constexpr int kIntervals = 32;
  double total[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i <= kIntervals; ++i) {
    const float mu = static_cast<float>(i) / kIntervals;
    const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    for (int c = 0; c < 3; ++c) total[c] += weight * fresnel_complex(mu, eta[c], k[c]) * mu;
  }
  Color average;
  for (int c = 0; c < 3; ++c) average[c] = static_cast<float>(2.0 * total[c] / (3.0 * kIntervals));
  return average;
}

// The path tracer builds a BSDF per shading point, mostly for the same few metals in a row: the
// last index seen per thread skips the hundred Fresnel evaluations of the integral. A pure
// function's memo, so results never depend on which thread shaded what.
Color complex_ior_average(const Color& eta, const Color& k) {
  struct Memo {
    Color eta, k, average;
    bool valid = false;
  };
  thread_local Memo last;
  if (!last.valid || last.eta != eta || last.k != k) last = {eta, k, integrate_complex_ior_average(eta, k), true};
  return last.average;
}

Color multiple_scattering_tint(const Color& fresnel_average, float average_albedo) {
  Color tint;
  for (int c = 0; c < 3; ++c) {
    const float f = fresnel_average[c];
    tint[c] = f * f * average_albedo / (1.0f - f * (1.0f - average_albedo));
  }
  return tint;
}

}  // namespace

float fresnel_complex(float cos_theta, float eta, float k) {
  using Complex = std::complex<float>;
  const float cos_i = std::clamp(cos_theta, 0.0f, 1.0f);
  const Complex n(eta, k);
  const Complex n2 = n * n;
  // sin²θt = sin²θi / n², divided through the conjugate: std::complex's division guards against
  // infinities at a cost that shows in a renderer's hot loop.
  const Complex sin2_t = (1.0f - cos_i * cos_i) * std::conj(n2) / std::norm(n2);
  const Complex cos_t = std::sqrt(1.0f - sin2_t);
  // |a/b|² = |a|²/|b|², so the reflection amplitudes need no division either.
  const float r_parallel = std::norm(n * cos_i - cos_t) / std::norm(n * cos_i + cos_t);
  const float r_perpendicular = std::norm(cos_i - n * cos_t) / std::norm(cos_i + n * cos_t);
  return (r_parallel + r_perpendicular) / 2.0f;
}

ConductorBsdf::ConductorBsdf(FresnelModel model, const Color& f0, const Color& eta, const Color& k, float alpha,
                             bool energy_compensation)
    : model_(model), f0_(f0), eta_(eta), k_(k), ggx_{alpha}, energy_compensation_(energy_compensation),
      fresnel_average_(model == FresnelModel::kSchlick ? schlick_average(f0) : complex_ior_average(eta, k)),
      // Read only where the lobe compensates: a conductor without compensation (a principled
      // material's unused metal lobe) leaves the albedo table unbuilt.
      average_albedo_(energy_compensation ? ggx_average_albedo(alpha) : 1.0f),
      multiple_scattering_tint_(multiple_scattering_tint(fresnel_average_, average_albedo_)) {}

ConductorBsdf ConductorBsdf::from_f0(const Color& f0, float alpha, bool energy_compensation) {
  return ConductorBsdf(FresnelModel::kSchlick, f0, Color(0.0f), Color(0.0f), alpha, energy_compensation);
}

ConductorBsdf ConductorBsdf::from_complex_ior(const Color& eta, const Color& k, float alpha, bool energy_compensation) {
  return ConductorBsdf(FresnelModel::kComplexIor, Color(0.0f), eta, k, alpha, energy_compensation);
}

Color ConductorBsdf::fresnel(float cos_theta) const {
  switch (model_) {
    case FresnelModel::kSchlick: {
      const float m = 1.0f - std::clamp(cos_theta, 0.0f, 1.0f);
      const float m5 = (m * m) * (m * m) * m;
      return f0_ + (Color(1.0f) - f0_) * m5;
    }
    case FresnelModel::kComplexIor:
      return {fresnel_complex(cos_theta, eta_.x, k_.x), fresnel_complex(cos_theta, eta_.y, k_.y),
              fresnel_complex(cos_theta, eta_.z, k_.z)};
  }
  return Color(0.0f);  // unreachable: the switch covers every model
}

ConductorBsdf::Outgoing ConductorBsdf::outgoing(const Vec3& wo) const {
  const float cos_o = abs_cos_theta(wo);
  if (!compensates()) return {cos_o, 1.0f, 1.0f};
  const float albedo = ggx_directional_albedo(cos_o, ggx_.alpha);
  const float single = albedo * channel_mean(fresnel_average_);
  const float multiple = (1.0f - albedo) * channel_mean(multiple_scattering_tint_);
  return {cos_o, albedo, single + multiple > 0.0f ? single / (single + multiple) : 1.0f};
}

std::optional<ConductorBsdf::Geometry> ConductorBsdf::geometry(const Vec3& wo, const Vec3& wi) const {
  if (!same_hemisphere(wo, wi) || ggx_.effectively_smooth()) return std::nullopt;
  const Vec3 half = wo + wi;
  const float half_length2 = dot(half, half);
  if (half_length2 == 0.0f) return std::nullopt;
  Vec3 wm = half / std::sqrt(half_length2);
  if (wm.z < 0.0f) wm = -wm;  // the facet normal faces out even when the surface is seen from behind
  return Geometry{wm, abs_cos_theta(wi), std::fabs(dot(wo, wm))};
}

Color ConductorBsdf::value(const Vec3& wo, const Vec3& wi, const Outgoing& o, const Geometry& g) const {
  const Color single = fresnel(g.wo_dot_wm) * (ggx_.d(g.wm) * ggx_.g(wo, wi) / (4.0f * g.cos_i * o.cos_o));
  const float missing_average = 1.0f - average_albedo_;
  if (!compensates() || missing_average <= 0.0f) return single;
  const float missing_i = 1.0f - ggx_directional_albedo(g.cos_i, ggx_.alpha);
  return single + multiple_scattering_tint_ * ((1.0f - o.albedo) * missing_i * kInvPi / missing_average);
}

float ConductorBsdf::density(const Vec3& wo, const Outgoing& o, const Geometry& g) const {
  // Reflection about wm doubles solid angles at the facet: dωm/dωi = 1 / (4 |wo·wm|).
  const float single = ggx_.visible_normal_pdf(wo, g.wm) / (4.0f * g.wo_dot_wm);
  if (o.p_single == 1.0f) return single;
  return o.p_single * single + (1.0f - o.p_single) * cosine_hemisphere_pdf(g.cos_i);
}

Color ConductorBsdf::eval(const Vec3& wo, const Vec3& wi) const {
  const std::optional<Geometry> g = geometry(wo, wi);
  return g ? value(wo, wi, outgoing(wo), *g) : Color(0.0f);
}

float ConductorBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  const std::optional<Geometry> g = geometry(wo, wi);
  return g ? density(wo, outgoing(wo), *g) : 0.0f;
}

std::optional<BsdfSample> ConductorBsdf::sample(const Vec3& wo, float u_lobe, Sample2D u) const {
  if (wo.z == 0.0f) return std::nullopt;
  if (ggx_.effectively_smooth()) {
    const Vec3 wi{-wo.x, -wo.y, wo.z};
    return BsdfSample{fresnel(abs_cos_theta(wi)) / abs_cos_theta(wi), wi, 1.0f, true, false, BsdfLobe::kGlossy};
  }
  const Outgoing o = outgoing(wo);
  Vec3 wi;
  if (u_lobe < o.p_single) {
    wi = -reflect(wo, ggx_.sample_visible_normal(wo, u));
  } else {
    wi = sample_cosine_hemisphere(u);
    if (wo.z < 0.0f) wi.z = -wi.z;
  }
  // Facets near the horizon reflect some directions into the surface: single scattering loses
  // that light (the compensation lobe returns its energy).
  const std::optional<Geometry> g = geometry(wo, wi);
  if (!g) return std::nullopt;
  const float pdf = density(wo, o, *g);
  if (pdf == 0.0f) return std::nullopt;
  return BsdfSample{value(wo, wi, o, *g), wi, pdf, false, false, BsdfLobe::kGlossy};
}

void ConductorBsdf::roughen_to(float min_alpha) {
  if (ggx_.alpha < min_alpha) *this = ConductorBsdf(model_, f0_, eta_, k_, min_alpha, energy_compensation_);
}

Vec3 bsdf_from(const ConductorSurface& conductor, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out) {
  const float alpha = roughness_to_alpha(conductor.roughness);
  const Color c = evaluate(base_color, point, textures);
  out.bsdf = conductor.has_complex_ior ? ConductorBsdf::from_complex_ior(conductor.eta, conductor.k, alpha)
                                       : ConductorBsdf::from_f0(c, alpha);
  out.albedo = c;
  return point.shading_normal;
}

}  // namespace rtpro
