// The film's layers resolved from known samples: the colour, the two half-buffers (even- and
// odd-indexed samples) and the variance of the pixel's mean.
#include "rtpro/render/film.h"
#include "rtpro/core/error.h"

#include <gtest/gtest.h>

#include <vector>

namespace rtpro {
namespace film_test {

std::vector<float> resolve(const std::vector<Aov>& aovs, const std::vector<Color>& samples) {
  const FilmLayout layout(aovs);
  PixelAccumulator acc;
  for (std::size_t s = 0; s < samples.size(); ++s) acc.add(samples[s], PrimaryHit{}, static_cast<int>(s));
  std::vector<float> pixel(static_cast<std::size_t>(layout.channel_count()));
  layout.resolve(acc, pixel);
  return pixel;
}

TEST(Film, HalvesAreTheMeansOfTheEvenAndOddSamples) {
  const FilmLayout layout({Aov::kHalves});
  EXPECT_EQ(layout.channels(), (std::vector<std::string>{"R", "G", "B", "half_a.R", "half_a.G", "half_a.B", "half_b.R",
                                                         "half_b.G", "half_b.B"}));
  const std::vector<float> p =
      resolve({Aov::kHalves}, {Color(1, 2, 3), Color(5, 6, 7), Color(3, 4, 5), Color(9, 10, 11), Color(2, 0, 0)});
  EXPECT_FLOAT_EQ(p[0], 20.0f / 5.0f);
  EXPECT_FLOAT_EQ(p[3], 6.0f / 3.0f);  // samples 0, 2, 4
  EXPECT_FLOAT_EQ(p[4], 6.0f / 3.0f);
  EXPECT_FLOAT_EQ(p[6], 14.0f / 2.0f);  // samples 1, 3
  EXPECT_FLOAT_EQ(p[8], 18.0f / 2.0f);
}

TEST(Film, OneSampleHasBothHalvesEqualToIt) {
  const std::vector<float> p = resolve({Aov::kHalves}, {Color(0.5f, 0.25f, 2.0f)});
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(p[3 + c], p[c]);
    EXPECT_EQ(p[6 + c], p[c]);
  }
}

TEST(Film, VarianceIsTheSampleVarianceOverTheSampleCount) {
  const std::vector<float> p =
      resolve({Aov::kVariance}, {Color(1, 0, 2), Color(3, 0, 2), Color(5, 0, 2), Color(7, 0, 2)});
  // Red: mean 4, sample variance ((9 + 1 + 1 + 9) / 3) = 20/3, of the mean 20/12.
  EXPECT_NEAR(p[3], 20.0f / 12.0f, 1e-5f);
  EXPECT_EQ(p[4], 0.0f);
  EXPECT_EQ(p[5], 0.0f);
  EXPECT_EQ(resolve({Aov::kVariance}, {Color(3, 3, 3)})[3], 0.0f);
}

TEST(Film, ExtraLayersLeaveTheColourBitIdentical) {
  const std::vector<Color> samples{Color(0.1f, 0.7f, 1e4f), Color(0.3f, 0.2f, 0.0f), Color(1e-3f, 5.0f, 0.25f)};
  const std::vector<float> plain = resolve({}, samples);
  const std::vector<float> layered = resolve({Aov::kHalves, Aov::kVariance, Aov::kAlbedo}, samples);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(plain[c], layered[c]);
}

TEST(Film, ParsesTheNewLayerNames) {
  EXPECT_EQ(parse_aov("halves"), Aov::kHalves);
  EXPECT_EQ(parse_aov("variance"), Aov::kVariance);
  EXPECT_THROW(parse_aov("halfs"), InputError);
}

}  // namespace film_test
}  // namespace rtpro
