// The sums a render keeps: only those its layers and adaptive sampling read, stored and merged so
// that the film's values equal one accumulator's over every sample.
#include "rtpro/render/pixel_sums.h"

#include "rtpro/render/film.h"

#include <gtest/gtest.h>

#include <vector>

namespace rtpro {
namespace pixel_sums_test {

PrimaryHit hit(std::uint32_t object_id, float depth) {
  PrimaryHit primary;
  primary.hit = true;
  primary.albedo = Color(0.25f, 0.5f, 0.75f);
  primary.normal = Vec3(0.0f, 1.0f, 0.0f);
  primary.depth = depth;
  primary.object_id = object_id;
  return primary;
}

// Samples [begin, end) of a pixel whose even samples hit object 7 and odd ones miss.
PixelAccumulator samples(int begin, int end) {
  PixelAccumulator acc;
  for (int s = begin; s < end; ++s)
    acc.add(Color(0.1f * static_cast<float>(s), 1.0f / static_cast<float>(s + 3), 2.0f),
            s % 2 == 0 ? hit(7, 2.5f) : PrimaryHit{}, s);
  return acc;
}

TEST(SumLayout, ColourOnlyKeepsFourFloatsAndEveryLayerAddsItsOwn) {
  EXPECT_EQ(SumLayout().floats(), 4);
  EXPECT_EQ(SumLayout({}, {}).floats(), 4);
  EXPECT_EQ(SumLayout({}, {.even_half = true}).floats(), 7);  // Cycles' error reads the even half
  EXPECT_EQ(SumLayout({}, {.squares = true}).floats(), 7);    // the relMSE error the squares
  const std::vector<Aov> spp{Aov::kSpp};
  EXPECT_EQ(SumLayout(spp, {}).floats(), 4);
  const std::vector<Aov> halves{Aov::kHalves};
  EXPECT_EQ(SumLayout(halves, {.even_half = true}).floats(), 10);
  const std::vector<Aov> all{Aov::kAlbedo, Aov::kNormal,   Aov::kDepth, Aov::kObjectId,
                             Aov::kHalves, Aov::kVariance, Aov::kSpp};
  EXPECT_EQ(SumLayout(all, {.even_half = true, .squares = true}).floats(), 4 + 3 + 3 + 3 + 3 + 3 + 2 + 1);
}

// Adds a pass's sums to the passes' before it, field by field: what the film must compute.
void add_pass(PixelAccumulator& total, const PixelAccumulator& pass) {
  if (pass.samples == 0) return;
  if (total.samples == 0) total.first_object_id = pass.first_object_id;
  total.radiance += pass.radiance;
  total.even_radiance += pass.even_radiance;
  total.odd_radiance += pass.odd_radiance;
  total.radiance_squared += pass.radiance_squared;
  total.albedo += pass.albedo;
  total.normal += pass.normal;
  total.depth_sum += pass.depth_sum;
  total.hits += pass.hits;
  total.samples += pass.samples;
}

// Passes merged in order give, bit for bit, what every layer resolves from the passes' sums added
// in pass order; a pass that did not sample the pixel changes nothing.
TEST(SumLayout, MergedPassesResolveAsOneAccumulatorOfEverySample) {
  const std::vector<Aov> all{Aov::kAlbedo, Aov::kNormal,   Aov::kDepth, Aov::kObjectId,
                             Aov::kHalves, Aov::kVariance, Aov::kSpp};
  const SumLayout sums(all, {.even_half = true, .squares = true});
  const FilmLayout layout(all);
  std::vector<float> film(static_cast<std::size_t>(sums.floats()), 0.0f), item(film.size());
  const int passes[][2] = {{0, 1}, {1, 2}, {2, 2}, {2, 4}, {4, 8}, {8, 8}, {8, 13}};
  PixelAccumulator whole;
  for (const auto& [begin, end] : passes) {
    const PixelAccumulator pass = samples(begin, end);
    sums.store(pass, item.data());
    sums.merge(film.data(), item.data());
    add_pass(whole, pass);
  }
  EXPECT_EQ(SumLayout::samples(film.data()), 13);
  std::vector<float> merged(static_cast<std::size_t>(layout.channel_count())), expected(merged.size());
  layout.resolve(sums.load(film.data()), merged);
  layout.resolve(whole, expected);
  for (std::size_t c = 0; c < merged.size(); ++c) EXPECT_EQ(merged[c], expected[c]) << layout.channels()[c];
  EXPECT_EQ(sums.load(film.data()).first_object_id, 8u);  // object 7, stored + 1
  EXPECT_EQ(sums.load(film.data()).hits, 7);
}

// The first sample's object id is the earliest pass's, even when a later pass's pixel missed.
TEST(SumLayout, TheFirstSamplesObjectIdStays) {
  const std::vector<Aov> ids{Aov::kObjectId};
  const SumLayout sums(ids, {});
  std::vector<float> film(static_cast<std::size_t>(sums.floats()), 0.0f), item(film.size());
  PixelAccumulator first;
  first.add(Color(1.0f), hit(41, 1.0f), 0);
  sums.store(first, item.data());
  sums.merge(film.data(), item.data());
  PixelAccumulator later;
  later.add(Color(1.0f), PrimaryHit{}, 1);
  sums.store(later, item.data());
  sums.merge(film.data(), item.data());
  EXPECT_EQ(sums.load(film.data()).first_object_id, 42u);
  EXPECT_EQ(sums.load(film.data()).samples, 2);
}

}  // namespace pixel_sums_test
}  // namespace rtpro
