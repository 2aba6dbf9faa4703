#pragma once
// Statistical checks shared by the BSDF tests: pbrt's χ² test of a sampler against its pdf (the
// light set's test uses it too), and the albedo a sampler estimates. Deterministic: every random
// number comes from mix64 of a seed.
#include "rtpro/core/random.h"
#include "rtpro/core/vec3.h"
#include "rtpro/render/sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <future>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rtpro::test {

inline constexpr float kOneMinusEpsilon = 1.0f - 0x1p-24f;

inline Vec3 direction(float cos_theta, float phi) {
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// Counter-based uniform numbers in [0, 1). Each call is its own statement inside, so results do
// not depend on the unspecified order in which a compiler evaluates function arguments.
class Uniforms {
 public:
  explicit Uniforms(std::uint64_t seed) : seed_(mix64(seed)) {}
  float next() { return to_unit_float(hash_combine(seed_, counter_++)); }
  Sample2D next_2d() {
    const float x = next();
    return {x, next()};
  }
  // A direction with cos θ uniform in [cos_min, cos_max] and φ uniform.
  Vec3 next_direction(float cos_min = -1.0f, float cos_max = 1.0f) {
    const float cos_theta = cos_min + (cos_max - cos_min) * next();
    return direction(cos_theta, 2.0f * std::numbers::pi_v<float> * next());
  }
  // bsdf.sample(wo, ·, ·) with the next u_lobe and u.
  template <class Bsdf>
  auto sample(const Bsdf& bsdf, const Vec3& wo) {
    const float u_lobe = next();
    return bsdf.sample(wo, u_lobe, next_2d());
  }

 private:
  std::uint64_t seed_;
  std::uint64_t counter_ = 0;
};

// The level each of `runs` independent tests must pass so that together they falsely fail with
// probability `alpha` (Šidák's correction).
inline double sidak_level(double alpha, int runs) { return 1.0 - std::pow(1.0 - alpha, 1.0 / runs); }

// Q(a, x), the regularised upper incomplete gamma function (Numerical Recipes' gammq): the
// χ² survival function is Q(dof/2, χ²/2).
inline double regularized_gamma_q(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double log_prefactor = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0) {
    double term = 1.0 / a, sum = term, ap = a;
    for (int n = 0; n < 100000 && std::fabs(term) > std::fabs(sum) * 1e-15; ++n) {
      ap += 1.0;
      term *= x / ap;
      sum += term;
    }
    return 1.0 - sum * std::exp(log_prefactor);
  }
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(log_prefactor) * h;
}

inline double chi2_survival(double chi2, int dof) { return regularized_gamma_q(0.5 * dof, 0.5 * chi2); }

struct Chi2Outcome {
  double p_value = 0.0;
  double chi2 = 0.0;
  int dof = 0;
  double pdf_integral = 0.0;      // ∫ pdf over the sphere, from the per-bin integrals
  double sampled_fraction = 0.0;  // the fraction of sample() calls that returned a direction
  std::string failure;            // why the test could not be carried out; empty otherwise
};

// ∫∫ pdf(θ, φ) sin θ dθ dφ over one cell by five-point Gauss-Legendre per axis: the nodes stay
// inside the cell, so a pdf that jumps at a cell edge (the horizon) is integrated from the right
// side.
template <class PdfFn>
double gauss_legendre_cell(PdfFn& pdf, double theta0, double theta1, double phi0, double phi1) {
  constexpr std::array<double, 5> kNodes{-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                         0.9061798459386640};
  constexpr std::array<double, 5> kWeights{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                           0.4786286704993665, 0.2369268850561891};
  std::array<double, 5> cos_phi{}, sin_phi{};
  for (int b = 0; b < 5; ++b) {
    const double phi = 0.5 * (phi0 + phi1) + 0.5 * (phi1 - phi0) * kNodes[b];
    cos_phi[b] = std::cos(phi);
    sin_phi[b] = std::sin(phi);
  }
  double sum = 0.0;
  for (int a = 0; a < 5; ++a) {
    const double theta = 0.5 * (theta0 + theta1) + 0.5 * (theta1 - theta0) * kNodes[a];
    const double sin_theta = std::sin(theta), cos_theta = std::cos(theta);
    for (int b = 0; b < 5; ++b) {
      const Vec3 w{static_cast<float>(sin_theta * cos_phi[b]), static_cast<float>(sin_theta * sin_phi[b]),
                   static_cast<float>(cos_theta)};
      sum += kWeights[a] * kWeights[b] * static_cast<double>(pdf(w)) * sin_theta;
    }
  }
  return 0.25 * (theta1 - theta0) * (phi1 - phi0) * sum;
}

// Where a caller says the quarters' agreement cannot be trusted, given (θ0, θ1, φ0, φ1) of a cell
// or part of one. Nowhere for the BSDFs.
struct NoForcedSplits {
  bool operator()(double, double, double, double) const { return false; }
};

// Adaptive: a cell is split in four while its quarters disagree with the whole, because pdfs
// jump inside cells too (where the facet joining wo and wi turns its back on one of them) and peak
// within a cell at small α, and a fixed rule misses there by more than the counts' noise. A pdf
// whose support can be thinner than the nodes' spacing (a light seen edge-on) is also split where
// `must_split` says its support's boundary runs, because there all nodes may read zero.
template <class PdfFn, class SplitFn = NoForcedSplits>
double integrate_over_cell(PdfFn& pdf, double theta0, double theta1, double phi0, double phi1, double whole,
                           int depth = 6, const SplitFn& must_split = {}) {
  const double theta_mid = 0.5 * (theta0 + theta1), phi_mid = 0.5 * (phi0 + phi1);
  const std::array<std::array<double, 4>, 4> quarters{{{theta0, theta_mid, phi0, phi_mid},
                                                       {theta0, theta_mid, phi_mid, phi1},
                                                       {theta_mid, theta1, phi0, phi_mid},
                                                       {theta_mid, theta1, phi_mid, phi1}}};
  std::array<double, 4> parts{};
  double sum = 0.0;
  for (int q = 0; q < 4; ++q) {
    parts[q] = gauss_legendre_cell(pdf, quarters[q][0], quarters[q][1], quarters[q][2], quarters[q][3]);
    sum += parts[q];
  }
  if (depth == 0 || (std::fabs(sum - whole) <= 1e-9 + 1e-4 * sum && !must_split(theta0, theta1, phi0, phi1)))
    return sum;
  double refined = 0.0;
  for (int q = 0; q < 4; ++q)
    refined += integrate_over_cell(pdf, quarters[q][0], quarters[q][1], quarters[q][2], quarters[q][3], parts[q],
                                   depth - 1, must_split);
  return refined;
}

inline constexpr int kThetaBins = 80;
inline constexpr int kPhiBins = 160;

// pbrt's χ² test (src/pbrt/bsdfs_test.cpp, from Mitsuba): histogram `sample_count` samples over
// kThetaBins × kPhiBins bins of the sphere, integrate pdf() over each bin for the expected counts,
// pool the bins expecting fewer than 5, and return the p-value of the observed counts.
// `sample(u_lobe, u)` returns a unit direction or nothing; `pdf(w)` its density per solid angle;
// `must_split` as integrate_over_cell reads it.
template <class SampleFn, class PdfFn, class SplitFn = NoForcedSplits>
Chi2Outcome chi2_test(SampleFn&& sample, PdfFn&& pdf, int sample_count, std::uint64_t seed,
                      const SplitFn& must_split = {}) {
  constexpr double kPi = std::numbers::pi;
  constexpr int kBins = kThetaBins * kPhiBins;
  Chi2Outcome outcome;

  std::vector<double> observed(kBins, 0.0);
  Uniforms uniforms(seed);
  int sampled = 0;
  for (int i = 0; i < sample_count; ++i) {
    const float u_lobe = uniforms.next();
    const std::optional<Vec3> w = sample(u_lobe, uniforms.next_2d());
    if (!w) continue;
    ++sampled;
    const double theta = std::acos(std::clamp(static_cast<double>(w->z), -1.0, 1.0));
    double phi = std::atan2(static_cast<double>(w->y), static_cast<double>(w->x));
    if (phi < 0.0) phi += 2.0 * kPi;
    const int t = std::min(static_cast<int>(theta / kPi * kThetaBins), kThetaBins - 1);
    const int p = std::min(static_cast<int>(phi / (2.0 * kPi) * kPhiBins), kPhiBins - 1);
    observed[t * kPhiBins + p] += 1.0;
  }
  outcome.sampled_fraction = static_cast<double>(sampled) / sample_count;

  const double d_theta = kPi / kThetaBins, d_phi = 2.0 * kPi / kPhiBins;
  std::vector<double> expected(kBins, 0.0);
  for (int t = 0; t < kThetaBins; ++t)
    for (int p = 0; p < kPhiBins; ++p) {
      const double theta0 = t * d_theta, theta1 = (t + 1) * d_theta, phi0 = p * d_phi, phi1 = (p + 1) * d_phi;
      const double whole = gauss_legendre_cell(pdf, theta0, theta1, phi0, phi1);
      const double integral = integrate_over_cell(pdf, theta0, theta1, phi0, phi1, whole, 6, must_split);
      outcome.pdf_integral += integral;
      expected[t * kPhiBins + p] = integral * sample_count;
    }

  std::vector<std::pair<double, int>> cells;
  for (int i = 0; i < kBins; ++i) cells.emplace_back(expected[i], i);
  std::sort(cells.begin(), cells.end());
  double pooled_observed = 0.0, pooled_expected = 0.0;
  for (const auto& [expected_count, index] : cells) {
    if (expected_count == 0.0) {
      if (observed[index] > sample_count * 1e-5) {
        outcome.failure = std::to_string(observed[index]) + " samples in a bin of zero expected count";
        return outcome;
      }
    } else if (expected_count < 5.0 || (pooled_expected > 0.0 && pooled_expected < 5.0)) {
      pooled_observed += observed[index];
      pooled_expected += expected_count;
    } else {
      const double diff = observed[index] - expected_count;
      outcome.chi2 += diff * diff / expected_count;
      ++outcome.dof;
    }
  }
  if (pooled_expected > 0.0 || pooled_observed > 0.0) {
    const double diff = pooled_observed - pooled_expected;
    outcome.chi2 += diff * diff / pooled_expected;
    ++outcome.dof;
  }
  outcome.dof -= 1;
  if (outcome.dof <= 0) {
    outcome.failure = "too few degrees of freedom";
    return outcome;
  }
  outcome.p_value = chi2_survival(outcome.chi2, outcome.dof);
  return outcome;
}

// Mean of f·|cos θi|/pdf over `count` samples (a square number): u stratified on a grid, u_lobe
// jittered; for a delta lobe pdf is its probability, so the same sum counts it.
template <class Bsdf>
Color estimate_albedo(const Bsdf& bsdf, const Vec3& wo, int count = 16384, std::uint64_t seed = 1) {
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(count))));
  Uniforms uniforms(seed);
  double sum[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const float u_lobe = uniforms.next();
      const Sample2D jitter = uniforms.next_2d();
      const Sample2D u{std::min((static_cast<float>(i) + jitter.x) / side, kOneMinusEpsilon),
                       std::min((static_cast<float>(j) + jitter.y) / side, kOneMinusEpsilon)};
      const auto s = bsdf.sample(wo, u_lobe, u);
      if (!s || s->pdf == 0.0f) continue;
      const float weight = std::fabs(s->wi.z) / s->pdf;
      for (int c = 0; c < 3; ++c) sum[c] += static_cast<double>(s->f[c]) * weight;
    }
  const double n = static_cast<double>(side) * side;
  return {static_cast<float>(sum[0] / n), static_cast<float>(sum[1] / n), static_cast<float>(sum[2] / n)};
}

inline constexpr int kChi2Samples = 500'000;
inline constexpr double kChi2Significance = 0.01;

// One χ² run per incident direction in `wos`, each at the Šidák-corrected level. Also checks that
// pdf() integrates to what the sampler delivers: 1 minus what it drops (microfacet reflections
// into the surface), and never above 1. Prints each run so the figures are on record. The runs
// are independent and each is deterministic, so they run concurrently.
template <class Bsdf>
void expect_sampler_matches_pdf(const std::string& label, const Bsdf& bsdf, const std::vector<Vec3>& wos,
                                int sample_count = kChi2Samples, double pdf_tolerance = 2e-3) {
  std::vector<std::future<Chi2Outcome>> runs;
  for (std::size_t run = 0; run < wos.size(); ++run)
    runs.push_back(std::async(std::launch::async, [&bsdf, wo = wos[run], sample_count, seed = 7919 * (run + 1)] {
      return chi2_test(
          [&](float u_lobe, Sample2D u) -> std::optional<Vec3> {
            const auto s = bsdf.sample(wo, u_lobe, u);
            if (!s) return std::nullopt;
            return s->wi;
          },
          [&](const Vec3& wi) { return bsdf.pdf(wo, wi); }, sample_count, seed);
    }));
  const double level = sidak_level(kChi2Significance, static_cast<int>(wos.size()));
  for (std::size_t run = 0; run < wos.size(); ++run) {
    const Chi2Outcome outcome = runs[run].get();
    const Vec3& wo = wos[run];
    std::cout << "[chi2] " << label << " wo.z=" << wo.z << " p=" << outcome.p_value << " chi2=" << outcome.chi2
              << " dof=" << outcome.dof << " pdf_integral=" << outcome.pdf_integral
              << " sampled=" << outcome.sampled_fraction << "\n";
    SCOPED_TRACE(label + ", wo.z = " + std::to_string(wo.z));
    EXPECT_TRUE(outcome.failure.empty()) << outcome.failure;
    EXPECT_GE(outcome.p_value, level) << "chi2 " << outcome.chi2 << " with " << outcome.dof << " dof";
    EXPECT_LE(outcome.pdf_integral, 1.0 + pdf_tolerance);
    EXPECT_NEAR(outcome.pdf_integral, outcome.sampled_fraction, pdf_tolerance);
  }
}

// ∫ f(wo, wi) μi dωi over the upper hemisphere, wo at cosine `mu` in the xz plane, by a midpoint
// rule over (x, φ) with μi = x² (nodes dense towards grazing wi) and φ over [0, π] (f symmetric
// about the plane of wo): an albedo to check tables and lobes against, without random numbers.
template <class F>
double hemisphere_albedo(float mu, int steps, F f) {
  const Vec3 wo{std::sqrt(1.0f - mu * mu), 0.0f, mu};
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double x = (i + 0.5) / steps;
    const float mu_i = static_cast<float>(x * x);
    const float sin_i = std::sqrt(1.0f - mu_i * mu_i);
    for (int j = 0; j < steps; ++j) {
      const float phi = std::numbers::pi_v<float> * (static_cast<float>(j) + 0.5f) / static_cast<float>(steps);
      sum += static_cast<double>(f(wo, Vec3{sin_i * std::cos(phi), sin_i * std::sin(phi), mu_i})) * mu_i * 2.0 * x;
    }
  }
  return sum * 2.0 * std::numbers::pi / (static_cast<double>(steps) * steps);
}

}  // namespace rtpro::test
