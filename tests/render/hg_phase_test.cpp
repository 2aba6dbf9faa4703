// The Henyey–Greenstein phase function: normalised, its mean cosine is g, and its sampler matches
// its pdf by pbrt's χ² protocol (bsdf_test_support.h).
#include "hg_phase.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <future>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

namespace rtpro {
namespace {

constexpr float kAnisotropies[] = {-0.7f, 0.0f, 0.0005f, 0.3f, 0.7f, 0.9f};

// ∫ f(cos θ) over the sphere by the midpoint rule in cos θ.
template <class F>
double sphere_integral(F f) {
  constexpr int kSteps = 200000;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double mu = -1.0 + (i + 0.5) * 2.0 / kSteps;
    sum += f(mu) * 2.0 / kSteps;
  }
  return 2.0 * std::numbers::pi * sum;
}

TEST(HenyeyGreenstein, IntegratesToOneWithMeanCosineG) {
  for (const float g : kAnisotropies) {
    SCOPED_TRACE("g = " + std::to_string(g));
    EXPECT_NEAR(sphere_integral([&](double mu) { return henyey_greenstein(static_cast<float>(mu), g); }), 1.0, 2e-3);
    EXPECT_NEAR(sphere_integral([&](double mu) { return mu * henyey_greenstein(static_cast<float>(mu), g); }), g, 2e-3);
  }
}

TEST(HenyeyGreenstein, ForwardMeansCarryingOn) {
  // Light travelling along +z scatters mostly on along +z for g > 0.
  const Vec3 incoming{0.0f, 0.0f, 1.0f};
  test::Uniforms u(3);
  double mean = 0.0;
  constexpr int kCount = 20000;
  for (int i = 0; i < kCount; ++i) mean += sample_henyey_greenstein(incoming, 0.7f, u.next_2d()).outgoing.z;
  EXPECT_NEAR(mean / kCount, 0.7, 0.02);
}

TEST(HenyeyGreensteinChi2, SamplerMatchesPdf) {
  // The incoming directions are tilted so the sampler's frame is not the histogram's.
  const std::vector<Vec3> incoming{normalize(Vec3{0.3f, -0.2f, 0.9f}), normalize(Vec3{-0.6f, 0.5f, -0.2f})};
  std::vector<std::future<test::Chi2Outcome>> runs;
  std::vector<std::string> labels;
  for (const float g : kAnisotropies)
    for (std::size_t d = 0; d < incoming.size(); ++d) {
      labels.push_back("g=" + std::to_string(g) + " incoming " + std::to_string(d));
      runs.push_back(std::async(std::launch::async, [g, in = incoming[d], seed = 101 * (runs.size() + 1)] {
        return test::chi2_test(
            [&](float, Sample2D u) -> std::optional<Vec3> { return sample_henyey_greenstein(in, g, u).outgoing; },
            [&](const Vec3& w) { return henyey_greenstein(dot(in, w), g); }, 200'000, seed);
      }));
    }
  const double level = test::sidak_level(test::kChi2Significance, static_cast<int>(runs.size()));
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const test::Chi2Outcome outcome = runs[i].get();
    std::cout << "[chi2] hg " << labels[i] << " p=" << outcome.p_value << " dof=" << outcome.dof << "\n";
    SCOPED_TRACE(labels[i]);
    EXPECT_TRUE(outcome.failure.empty()) << outcome.failure;
    EXPECT_GE(outcome.p_value, level);
    EXPECT_NEAR(outcome.pdf_integral, 1.0, 2e-3);
  }
}

TEST(HenyeyGreenstein, SampledPdfIsTheValue) {
  test::Uniforms u(5);
  const Vec3 incoming = normalize(Vec3{1.0f, 2.0f, -0.5f});
  for (int i = 0; i < 1000; ++i) {
    const PhaseSample s = sample_henyey_greenstein(incoming, -0.4f, u.next_2d());
    EXPECT_NEAR(length(s.outgoing), 1.0f, 1e-5f);
    EXPECT_NEAR(s.pdf, henyey_greenstein(dot(incoming, s.outgoing), -0.4f), 1e-3f * s.pdf);
  }
}

}  // namespace
}  // namespace rtpro
