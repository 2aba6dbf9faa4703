// The two noise metrics of adaptive sampling against their formulas: Cycles' error is the same for
// every pixel at its threshold, the relMSE error is the marginal gain of one more sample, so it
// falls as 1/n and ranks pixels by their relative noise, not their brightness.
#include "rtpro/render/adaptive_sampling.h"

#include "rtpro/core/error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rtpro {
namespace adaptive_sampling_test {

// n samples alternating between mean·(1 − spread) and mean·(1 + spread), grey.
PixelAccumulator alternating(float mean, float spread, int n) {
  PixelAccumulator acc;
  for (int s = 0; s < n; ++s) acc.add(Color(mean * (s % 2 == 0 ? 1.0f - spread : 1.0f + spread)), PrimaryHit{}, s);
  return acc;
}

TEST(NoiseMetric, RelMseErrorIsTheSquareRootOfTheMarginalGainOfASample) {
  const int n = 64;
  const PixelAccumulator acc = alternating(2.0f, 0.5f, n);
  // Samples 1 and 3: sample variance n/(n−1), the mean's n/(n−1)/n, relative to 2² + 0.01.
  const double relmse = (64.0 / 63.0 / 64.0) / (4.0 + 0.01);
  EXPECT_NEAR(pixel_error(acc, NoiseMetric::kRelMse), std::sqrt(relmse / 64.0), 1e-6);
  // Four times the samples of the same noise: a quarter of the marginal gain.
  const float quadrupled = pixel_error(alternating(2.0f, 0.5f, 4 * n), NoiseMetric::kRelMse);
  EXPECT_NEAR(quadrupled / pixel_error(acc, NoiseMetric::kRelMse), 0.25f, 0.01f);
}

TEST(NoiseMetric, RelMseRanksByRelativeNoiseAndCyclesByBrightnessToo) {
  // The same relative noise, one pixel 16 times brighter.
  const PixelAccumulator dim = alternating(1.0f, 0.3f, 32), bright = alternating(16.0f, 0.3f, 32);
  EXPECT_NEAR(pixel_error(bright, NoiseMetric::kRelMse) / pixel_error(dim, NoiseMetric::kRelMse), 1.0f, 0.01f);
  // Cycles': |I − A| grows with the brightness, √I less: 16/4 = 4 times the error.
  EXPECT_NEAR(pixel_error(bright, NoiseMetric::kCycles) / pixel_error(dim, NoiseMetric::kCycles), 4.0f, 0.01f);
}

TEST(NoiseMetric, NeedsTwoSamplesAndParsesItsNames) {
  EXPECT_TRUE(std::isinf(pixel_error(alternating(1.0f, 0.5f, 1), NoiseMetric::kRelMse)));
  EXPECT_TRUE(std::isinf(pixel_error(alternating(1.0f, 0.5f, 1), NoiseMetric::kCycles)));
  EXPECT_EQ(parse_noise_metric("relmse"), NoiseMetric::kRelMse);
  EXPECT_EQ(parse_noise_metric("cycles"), NoiseMetric::kCycles);
  EXPECT_STREQ(noise_metric_name(NoiseMetric::kRelMse), "relmse");
  EXPECT_THROW(parse_noise_metric("mse"), InputError);
}

}  // namespace adaptive_sampling_test
}  // namespace rtpro
