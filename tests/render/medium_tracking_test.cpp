// Tracking through a homogeneous slab: the fraction delta tracking lets through, ratio tracking's
// estimate and the closed form all equal exp(−σt·d) within their noise; a grey albedo-1 medium
// never absorbs; emission integrates to ε·(1 − exp(−σt·d))/σt.
#include "medium_tracking.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rtpro {
namespace {

// A ray along +x through a slab [0, d).
Ray slab_ray() { return Ray{{0.0f, 0.0f, 0.0f}, 0.0f, {1.0f, 0.0f, 0.0f}, std::numeric_limits<float>::infinity()}; }

constexpr int kWalks = 40000;

// Mean and standard error of `estimate(i)` over kWalks walks.
template <class F>
std::pair<double, double> mean_and_error(F estimate) {
  double sum = 0.0, squares = 0.0;
  for (int i = 0; i < kWalks; ++i) {
    const double x = estimate(i);
    sum += x;
    squares += x * x;
  }
  const double mean = sum / kWalks;
  return {mean, std::sqrt(std::max(0.0, squares / kWalks - mean * mean) / kWalks)};
}

TEST(MediumTracking, SlabTransmittanceByDeltaAndRatioTracking) {
  const Medium medium = HomogeneousMedium{{0.3f, 0.6f, 1.2f}, {0.5f, 0.4f, 0.3f}, 0.3f, Color(0.0f)};
  constexpr float kDepth = 1.5f;
  const Color sigma_t{0.8f, 1.0f, 1.5f};
  TrackingRandom closed_random(1);
  const Color closed = transmittance(medium, slab_ray(), kDepth, closed_random);
  for (int c = 0; c < 3; ++c) {
    const double expected = std::exp(-sigma_t[c] * kDepth);
    SCOPED_TRACE("channel " + std::to_string(c));
    EXPECT_NEAR(closed[c], expected, 1e-6);
    const auto [ratio, ratio_error] = mean_and_error([&](int i) {
      TrackingRandom random(mix64(i));
      return ratio_tracking(medium, slab_ray(), kDepth, random)[c];
    });
    EXPECT_NEAR(ratio, expected, 5.0 * ratio_error + 1e-4);
    // Delta tracking: the path's throughput after the slab, 0 when it scattered or was absorbed.
    const auto [delta, delta_error] = mean_and_error([&](int i) {
      TrackingRandom random(mix64(i) ^ 0x5555);
      const TrackedRay tracked = delta_track(medium, slab_ray(), kDepth, random.next(), random, Color(1.0f));
      return tracked.event == TrackedRay::Event::kPassed ? tracked.beta[c] : 0.0f;
    });
    EXPECT_NEAR(delta, expected, 5.0 * delta_error + 1e-4);
    EXPECT_NEAR(delta, ratio, 5.0 * std::hypot(delta_error, ratio_error) + 1e-4);
  }
}

TEST(MediumTracking, GreyAlbedoOneMediumOnlyScattersOrPasses) {
  const Medium medium = HomogeneousMedium{Color(0.0f), Color(2.0f), -0.7f, Color(0.0f)};
  int passed = 0;
  for (int i = 0; i < kWalks; ++i) {
    TrackingRandom random(mix64(i));
    const TrackedRay tracked = delta_track(medium, slab_ray(), 1.0f, random.next(), random, Color(1.0f));
    ASSERT_NE(tracked.event, TrackedRay::Event::kAbsorbed);
    EXPECT_EQ(tracked.beta, Color(1.0f));  // analogue: every weight is 1
    if (tracked.event == TrackedRay::Event::kScattered) {
      EXPECT_GE(tracked.t, 0.0f);
      EXPECT_LT(tracked.t, 1.0f);
      EXPECT_EQ(tracked.anisotropy, -0.7f);
    }
    passed += tracked.event == TrackedRay::Event::kPassed;
  }
  const double p = std::exp(-2.0);
  EXPECT_NEAR(double(passed) / kWalks, p, 5.0 * std::sqrt(p * (1 - p) / kWalks));
}

TEST(MediumTracking, EmissionIntegratesAlongTheRay) {
  // Absorbing and emitting: L = ε (1 − e^{−σa d}) / σa collected by delta tracking.
  const Medium medium = HomogeneousMedium{Color(0.7f), Color(0.0f), 0.0f, Color(0.5f, 1.0f, 2.0f)};
  constexpr float kDepth = 2.0f;
  for (int c = 0; c < 3; ++c) {
    const auto [mean, error] = mean_and_error([&](int i) {
      TrackingRandom random(mix64(i) + 17);
      return delta_track(medium, slab_ray(), kDepth, random.next(), random, Color(1.0f)).emitted[c];
    });
    const double expected =
        medium_point(std::get<HomogeneousMedium>(medium), {}).emission[c] * (1.0 - std::exp(-0.7 * kDepth)) / 0.7;
    EXPECT_NEAR(mean, expected, 5.0 * error + 1e-4);
  }
}

TEST(MediumTracking, AbsorbingOnlyMediumAttenuatesInClosedForm) {
  const Medium medium = HomogeneousMedium{{0.1f, 0.0f, 3.0f}, Color(0.0f), 0.0f, Color(0.0f)};
  TrackingRandom random(9);
  const TrackedRay tracked = delta_track(medium, slab_ray(), 2.0f, 0.5f, random, Color(2.0f));
  EXPECT_EQ(tracked.event, TrackedRay::Event::kPassed);
  EXPECT_FLOAT_EQ(tracked.beta.x, 2.0f * std::exp(-0.2f));
  EXPECT_EQ(tracked.beta.y, 2.0f);
  // A ray without end: the channel that does not attenuate gets through, the others do not.
  const TrackedRay endless =
      delta_track(medium, slab_ray(), std::numeric_limits<float>::infinity(), 0.5f, random, Color(1.0f));
  EXPECT_EQ(endless.beta, Color(0.0f, 1.0f, 0.0f));
}

TEST(MediumTracking, GlassAbsorptionIsItsColourAfterItsDistanceAndRatioTrackingAgrees) {
  // Tinted glass: white light is (0.5, 0.8, 1) after 2 units, and an opaque channel stays 0.
  const Medium medium = AbsorbingMedium{{0.5f, 0.8f, 0.0f}, 2.0f};
  TrackingRandom random(11);
  const Color closed = transmittance(medium, slab_ray(), 3.0f, random);
  EXPECT_FLOAT_EQ(closed.x, std::pow(0.5f, 1.5f));
  EXPECT_FLOAT_EQ(closed.y, std::pow(0.8f, 1.5f));
  EXPECT_EQ(closed.z, 0.0f);
  const TrackedRay tracked = delta_track(medium, slab_ray(), 3.0f, 0.5f, random, Color(1.0f));
  EXPECT_EQ(tracked.event, TrackedRay::Event::kPassed);
  EXPECT_EQ(tracked.beta, closed);
  // Its coefficients, σa = −ln(colour)/distance, are what ratio tracking walks by.
  const Color tint{0.5f, 0.8f, 0.9f};
  const Medium tinted = AbsorbingMedium{tint, 2.0f};
  for (int c = 0; c < 3; ++c) {
    const auto [ratio, error] = mean_and_error([&](int i) {
      TrackingRandom walk(mix64(i) ^ 0x77);
      return ratio_tracking(tinted, slab_ray(), 3.0f, walk)[c];
    });
    EXPECT_NEAR(ratio, std::pow(tint[c], 1.5f), 5.0 * error + 1e-4) << "channel " << c;
  }
}

TEST(MediumTracking, EndlessRayThroughAColouredFogKeepsTheUntouchedChannel) {
  // Scattering in red only: green and blue go to infinity; red scatters or is absorbed.
  const Medium medium = HomogeneousMedium{Color(0.0f), {1.0f, 0.0f, 0.0f}, 0.0f, Color(0.0f)};
  TrackingRandom random(4);
  const TrackedRay tracked =
      delta_track(medium, slab_ray(), std::numeric_limits<float>::infinity(), 0.3f, random, Color(0.0f, 1.0f, 1.0f));
  EXPECT_EQ(tracked.event, TrackedRay::Event::kPassed);
  EXPECT_EQ(tracked.beta, Color(0.0f, 1.0f, 1.0f));
}

}  // namespace
}  // namespace rtpro
