// Piecewise-constant distributions: the pdf integrates to 1, samples land in proportion to the
// values, cells of value 0 are never sampled, and the pdf returned with a sample is pdf() there.
#include "rtpro/render/distribution_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace rtpro {
namespace distribution_2d_test {

// A well-spread sequence in [0, 1): the golden-ratio (Weyl) sequence.
float weyl(int i) {
  const double x = 0.6180339887498949 * static_cast<double>(i + 1);
  return static_cast<float>(x - std::floor(x));
}

// The R2 sequence (Roberts 2018): well spread over [0, 1)².
Sample2D r2(int i) {
  const double n = i + 1;
  const double x = 0.5 + 0.7548776662466927 * n, y = 0.5 + 0.5698402909980532 * n;
  return {static_cast<float>(x - std::floor(x)), static_cast<float>(y - std::floor(y))};
}

TEST(Distribution1D, SamplesEachCellInProportionToItsValue) {
  const std::vector<float> values{1.0f, 0.0f, 3.0f, 0.5f, 0.0f, 10.0f, 2.0f};
  const Distribution1D d(values);
  double total = 0.0;
  for (float v : values) total += v;
  EXPECT_NEAR(d.integral(), total / values.size(), 1e-6);
  std::vector<int> counts(values.size(), 0);
  constexpr int kSamples = 200000;
  for (int i = 0; i < kSamples; ++i) {
    const Distribution1D::Sample s = d.sample(weyl(i));
    ASSERT_GE(s.x, 0.0f);
    ASSERT_LT(s.x, 1.0f);
    ASSERT_EQ(s.cell, static_cast<std::size_t>(s.x * values.size())) << "x " << s.x;
    EXPECT_FLOAT_EQ(s.pdf, d.pdf(s.cell));
    ++counts[s.cell];
  }
  for (std::size_t c = 0; c < values.size(); ++c) {
    const double p = values[c] / total;
    EXPECT_NEAR(counts[c] / double(kSamples), p, 1e-3) << "cell " << c;
    // The density times the cell width is the cell's probability.
    EXPECT_NEAR(d.pdf(c) / values.size(), p, 1e-6) << "cell " << c;
  }
  EXPECT_EQ(counts[1], 0);
  EXPECT_EQ(counts[4], 0);
}

TEST(Distribution1D, AllZeroNegativeOrNonFiniteValuesGiveTheUniformDistribution) {
  const std::vector<float> values{0.0f, -1.0f, std::nanf(""), 0.0f};
  const Distribution1D d(values);
  for (std::size_t c = 0; c < values.size(); ++c) EXPECT_FLOAT_EQ(d.pdf(c), 1.0f);
  EXPECT_NEAR(d.sample(0.3f).x, 0.3f, 1e-6f);
  EXPECT_EQ(d.sample(0.99999994f).cell, 3u);
}

TEST(Distribution1D, ExtremeUStaysInsideTheCellsThatHaveProbability) {
  const std::vector<float> values{0.0f, 0.0f, 1.0f, 0.0f};
  const Distribution1D d(values);
  for (float u : {0.0f, 1e-9f, 0.5f, 0.99999994f}) {
    const Distribution1D::Sample s = d.sample(u);
    EXPECT_EQ(s.cell, 2u) << "u " << u;
    EXPECT_GE(s.x, 0.5f);
    EXPECT_LT(s.x, 0.75f);
  }
}

TEST(Distribution2D, PdfIntegratesToOneAndSamplesFollowIt) {
  constexpr int kWidth = 12, kHeight = 5;
  std::vector<float> values(kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) values[y * kWidth + x] = (x * 7 + y * 3) % 5 == 0 ? 0.0f : float(1 + (x ^ y));
  const Distribution2D d(values, kWidth, kHeight);
  double integral = 0.0, total = 0.0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      integral += d.pdf((x + 0.5f) / kWidth, (y + 0.5f) / kHeight) / (kWidth * kHeight);
      total += values[y * kWidth + x];
    }
  EXPECT_NEAR(integral, 1.0, 1e-5);
  std::vector<int> counts(values.size(), 0);
  constexpr int kSamples = 300000;
  for (int i = 0; i < kSamples; ++i) {
    const Distribution2D::Sample s = d.sample(r2(i));
    ASSERT_LT(s.u, 1.0f);
    ASSERT_LT(s.v, 1.0f);
    EXPECT_FLOAT_EQ(s.pdf, d.pdf(s.u, s.v));
    ++counts[static_cast<int>(s.v * kHeight) * kWidth + static_cast<int>(s.u * kWidth)];
  }
  for (int c = 0; c < kWidth * kHeight; ++c) {
    const double p = values[c] / total;
    if (p == 0.0) EXPECT_EQ(counts[c], 0) << "cell " << c;
    else EXPECT_NEAR(counts[c] / double(kSamples), p, 5.0 * std::sqrt(p * (1.0 - p) / kSamples) + 1e-4) << "cell " << c;
  }
}

}  // namespace distribution_2d_test
}  // namespace rtpro
