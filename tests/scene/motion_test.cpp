// scene/motion.h's shutter shapes: a camera sample's time is distributed as the shutter exposes.
#include "rtpro/scene/motion.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <vector>

namespace rtpro {
namespace motion_test {

// The exposure of the trapezoid [a, b] from the shutter's start to t, over its whole exposure.
double exposure_until(double a, double b, double t) {
  const double whole = 0.5 * (1.0 + b - a);
  double area = 0.0;
  if (a > 0.0) area += 0.5 * std::min(t, a) * std::min(t, a) / a;
  if (t > a) area += std::min(t, b) - a;
  if (t > b) area += 0.5 * (1.0 - b) - 0.5 * (1.0 - t) * (1.0 - t) / (1.0 - b);
  return area / whole;
}

TEST(ShutterTime, ABoxShutterKeepsTheSampleBitForBit) {
  const Shutter box{-0.25f, 0.25f};
  ASSERT_TRUE(box.is_box());
  for (int i = 0; i < 4096; ++i) {
    const float u = (static_cast<float>(i) + 0.37f) / 4096.0f;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(shutter_time(box, u)), std::bit_cast<std::uint32_t>(u)) << u;
  }
}

TEST(ShutterTime, TimesFollowTheTrapezoidsExposure) {
  // Each shape's sample times, from evenly spaced u, fall below t as often as the shutter has
  // exposed by t (the cumulative exposure's inverse), ramps, plateau and triangle alike.
  const std::vector<std::pair<float, float>> shapes = {{0.25f, 0.75f}, {0.5f, 0.5f}, {0.0f, 0.5f},
                                                       {0.3f, 1.0f},   {0.0f, 0.0f}, {1.0f, 1.0f}};
  constexpr int kSamples = 100000;
  for (const auto& [a, b] : shapes) {
    Shutter shutter{0.0f, 1.0f};
    shutter.opening = a;
    shutter.closing = b;
    ASSERT_FALSE(shutter.is_box());
    std::vector<float> times;
    float previous = 0.0f;
    for (int i = 0; i < kSamples; ++i) {
      const float t = shutter_time(shutter, (static_cast<float>(i) + 0.5f) / kSamples);
      ASSERT_TRUE(t >= 0.0f && t <= 1.0f) << t;
      ASSERT_GE(t, previous) << "not monotone in u";
      previous = t;
      times.push_back(t);
    }
    for (int k = 1; k < 20; ++k) {
      const double t = k / 20.0;
      const double below =
          static_cast<double>(std::lower_bound(times.begin(), times.end(), static_cast<float>(t)) - times.begin()) /
          kSamples;
      EXPECT_NEAR(below, exposure_until(a, b, t), 2e-5) << "shape [" << a << ", " << b << "] at t = " << t;
    }
  }
}

}  // namespace motion_test
}  // namespace rtpro
