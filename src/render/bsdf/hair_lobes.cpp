#include "hair_lobes.h"

#include "dielectric.h"
#include "rtpro/core/math_constants.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

namespace {

// The logistic density and distribution function of scale s.
float logistic(float x, float s) {
  const float e = std::exp(-std::fabs(x) / s);
  return e / (s * (1.0f + e) * (1.0f + e));
}
float logistic_cdf(float x, float s) { return 1.0f / (1.0f + std::exp(-x / s)); }

}  // namespace

// The power series Σ (x²/4)^i / (i!)², summed until its terms stop counting: at x = 12, where
// the asymptotic form takes over, pbrt's ten terms would leave 0.3% out.
float bessel_i0(float x) {
  const float quarter_x2 = 0.25f * x * x;
  float term = 1.0f, sum = 1.0f;
  for (int i = 1; i < 64 && term > sum * 1e-8f; ++i) {
    term *= quarter_x2 / static_cast<float>(i * i);
    sum += term;
  }
  return sum;
}

// ln(I0(x) e^−x) = −½ ln(2πx) + ln(1 + 1/(8x) + 9/(128x²) + …) for large x (the last to second
// order, within 1e-5 from x = 12 on): what M_p's low-variance form needs, where I0 overflows.
float log_scaled_bessel_i0(float x) {
  if (x <= 12.0f) return std::log(bessel_i0(x)) - x;
  return -0.5f * std::log(2.0f * kPi * x) + 1.0f / (8.0f * x) + 1.0f / (16.0f * x * x);
}

float log_bessel_i0(float x) { return log_scaled_bessel_i0(x) + x; }

// M_p = e^(−b) I0(a) / (2v sinh(1/v)) with a = cos θi cos θo / v and b = sin θi sin θo / v. For
// small v it is exp(ln(I0(a) e^−a) − (1 − cos(θi + θo))/v − ln v), since a − b = cos(θi + θo)/v and
// 1/(2v sinh(1/v)) → e^(−1/v)/v: pbrt's form, with 1 − cos(θi + θo) worked out without the
// cancellation that, at v near 1e-6, cost it most of the exponent's digits at the peak.
float longitudinal_scattering(float cos_i, float cos_o, float sin_i, float sin_o, float v) {
  const float a = cos_i * cos_o / v;
  if (v > 0.1f) return std::exp(-sin_i * sin_o / v) * bessel_i0(a) / (2.0f * v * std::sinh(1.0f / v));
  const float cos_sum = cos_i * cos_o - sin_i * sin_o;
  const float sin_sum = sin_i * cos_o + cos_i * sin_o;
  const float one_minus_cos = cos_sum > 0.0f ? sin_sum * sin_sum / (1.0f + cos_sum) : 1.0f - cos_sum;
  return std::exp(log_scaled_bessel_i0(a) - one_minus_cos / v - std::log(v));
}

// Inverts the distribution of cos θ about the cone's axis, exp((cos θ − 1)/v) normalised over
// cos θ in [−1, 1]; u = 0 (where exp(−2/v) underflows) gives the far pole.
float sample_longitudinal_cosine(float u, float v) {
  const float cos_theta = 1.0f + v * std::log(u + (1.0f - u) * std::exp(-2.0f / v));
  return std::clamp(cos_theta, -1.0f, 1.0f);
}

float trimmed_logistic(float x, float s) { return logistic(x, s) / (logistic_cdf(kPi, s) - logistic_cdf(-kPi, s)); }

float sample_trimmed_logistic(float u, float s) {
  const float low = logistic_cdf(-kPi, s);
  const float k = logistic_cdf(kPi, s) - low;
  const float x = -s * std::log(1.0f / (u * k + low) - 1.0f);
  return std::clamp(x, -kPi, kPi);
}

float exit_azimuth(int p, float gamma_o, float gamma_t) {
  return 2.0f * static_cast<float>(p) * gamma_t - 2.0f * gamma_o + static_cast<float>(p) * kPi;
}

float azimuthal_scattering(float dphi, int p, float s, float gamma_o, float gamma_t) {
  float d = dphi - exit_azimuth(p, gamma_o, gamma_t);
  // exit_azimuth reaches 3π + 4γ at p = 2 and Δφ spans 2π either way: a few turns at most.
  d = std::remainder(d, 2.0f * kPi);
  return trimmed_logistic(d, s);
}

std::array<Color, kHairLobes> hair_attenuation(float cos_theta_o, float eta, float h, const Color& transmittance) {
  std::array<Color, kHairLobes> a;
  const float cos_gamma_o = std::sqrt(std::max(0.0f, 1.0f - h * h));
  const float f = fresnel_dielectric(cos_theta_o * cos_gamma_o, eta);
  a[0] = Color(f);
  a[1] = transmittance * ((1.0f - f) * (1.0f - f));
  for (int p = 2; p < kHairLobes - 1; ++p) a[p] = a[p - 1] * transmittance * f;
  // Σ_{p ≥ pmax} a[pmax − 1] (fT)^(p − pmax + 1), channel by channel; nothing when fT = 1 would
  // make it diverge (f = 1 only at grazing incidence, where a[1] is 0 already).
  const Color ft = transmittance * f;
  for (int c = 0; c < 3; ++c)
    a[kHairLobes - 1][c] = ft[c] < 1.0f ? a[kHairLobes - 2][c] * ft[c] / (1.0f - ft[c]) : 0.0f;
  return a;
}

// Chiang et al.'s fit for R; TT is narrower and TRT wider (v/4 and 4v), the residual as TRT.
std::array<float, kHairLobes> longitudinal_variances(float beta_m) {
  const float b = beta_m;
  const float root = 0.726f * b + 0.812f * b * b + 3.7f * std::pow(b, 20.0f);
  const float v = root * root;
  std::array<float, kHairLobes> variances;
  variances[0] = v;
  variances[1] = 0.25f * v;
  for (int p = 2; p < kHairLobes; ++p) variances[p] = 4.0f * v;
  return variances;
}

float azimuthal_scale(float beta_n) {
  constexpr float kSqrtPiOver8 = 0.626657069f;
  const float b = beta_n;
  return kSqrtPiOver8 * (0.265f * b + 1.194f * b * b + 5.372f * std::pow(b, 22.0f));
}

}  // namespace rtpro
