// The sampling helpers every BSDF kind shares: the quarter-turn sine and cosine against libm's in
// double precision, and the concentric disk mapping built on them (on the disk, area-preserving
// per stratum, and the same map as the libm-based form up to rounding).
#include "bsdf_sample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rtpro {
namespace bsdf_sample_test {

// |a − exact| in units of the float spacing at `exact`.
double ulps_off(float a, double exact) {
  const float f = static_cast<float>(exact);
  const double ulp = std::nextafter(std::fabs(f), INFINITY) - std::fabs(f);
  return std::fabs(a - exact) / ulp;
}

TEST(BsdfSample, QuarterTurnSineCosineWithinTwoUlps) {
  constexpr int kSteps = 1 << 20;
  const float quarter = std::numbers::pi_v<float> / 4.0f;
  double worst_sin = 0.0, worst_cos = 0.0;
  for (int i = 0; i <= kSteps; ++i) {
    const float theta = -quarter + 2.0f * quarter * static_cast<float>(i) / kSteps;
    const SineCosine sc = sine_cosine_within_quarter_turn(theta);
    if (theta != 0.0f) worst_sin = std::max(worst_sin, ulps_off(sc.sin, std::sin(double(theta))));
    worst_cos = std::max(worst_cos, ulps_off(sc.cos, std::cos(double(theta))));
  }
  EXPECT_LE(worst_sin, 2.0);
  EXPECT_LE(worst_cos, 2.0);
  EXPECT_EQ(sine_cosine_within_quarter_turn(0.0f).sin, 0.0f);
  EXPECT_EQ(sine_cosine_within_quarter_turn(0.0f).cos, 1.0f);
}

TEST(BsdfSample, ConcentricMappingIsTheDiskMapUpToRounding) {
  constexpr int kGrid = 512;
  int outside = 0;
  double worst = 0.0;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const Sample2D u{(i + 0.5f) / kGrid, (j + 0.37f) / kGrid};
      const Sample2D d = sample_uniform_disk_concentric(u);
      // Shirley–Chiu in double precision.
      const double x = 2.0 * u.x - 1.0, y = 2.0 * u.y - 1.0;
      const double r = std::fabs(x) > std::fabs(y) ? x : y;
      const double phi = std::fabs(x) > std::fabs(y) ? std::numbers::pi / 4 * (y / x)
                                                     : std::numbers::pi / 2 - std::numbers::pi / 4 * (x / y);
      worst = std::max({worst, std::fabs(d.x - r * std::cos(phi)), std::fabs(d.y - r * std::sin(phi))});
      if (double(d.x) * d.x + double(d.y) * d.y > 1.0 + 1e-6) ++outside;
    }
  EXPECT_LT(worst, 4e-7);
  EXPECT_EQ(outside, 0);
  const Sample2D centre = sample_uniform_disk_concentric({0.5f, 0.5f});
  EXPECT_EQ(centre.x, 0.0f);
  EXPECT_EQ(centre.y, 0.0f);
}

// The cosine-weighted hemisphere stays unit length and above the surface.
TEST(BsdfSample, CosineHemisphereDirectionsAreUnitAndUpward) {
  constexpr int kGrid = 256;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const Vec3 w = sample_cosine_hemisphere({(i + 0.25f) / kGrid, (j + 0.75f) / kGrid});
      ASSERT_NEAR(length(w), 1.0f, 1e-6f);
      ASSERT_GE(w.z, 0.0f);
    }
}

}  // namespace bsdf_sample_test
}  // namespace rtpro
