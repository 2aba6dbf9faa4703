#include "alias_table.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace rtpro {
namespace alias_table_test {

TEST(AliasTable, PicksInProportionToWeight) {
  const std::vector<float> weights{1.0f, 0.0f, 3.0f, 0.5f, 10.0f, 0.25f};
  const AliasTable table(weights);
  ASSERT_EQ(table.size(), weights.size());
  float total = 0.0f;
  for (const float w : weights) total += w;
  std::vector<double> counts(weights.size(), 0.0);
  constexpr int kSamples = 1'000'000;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i < kSamples; ++i) {
    const AliasTable::Pick pick = table.sample(uniform(rng));
    ASSERT_LT(pick.index, weights.size());
    EXPECT_FLOAT_EQ(pick.pmf, weights[pick.index] / total);
    EXPECT_GE(pick.remapped_u, 0.0f);
    EXPECT_LT(pick.remapped_u, 1.0f);
    counts[pick.index] += 1.0;
  }
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const double p = weights[i] / total;
    EXPECT_FLOAT_EQ(table.pmf(static_cast<std::uint32_t>(i)), static_cast<float>(p));
    // Five standard deviations of a binomial count.
    EXPECT_NEAR(counts[i] / kSamples, p, 5.0 * std::sqrt(p * (1.0 - p) / kSamples) + 1e-7) << "item " << i;
  }
  EXPECT_EQ(counts[1], 0.0);  // a zero weight is never picked
}

TEST(AliasTable, EveryUInTheUnitIntervalGivesAValidPick) {
  const AliasTable table(std::vector<float>{2.0f, 1.0f, 1.0f});
  for (const float u : {0.0f, 0.3333333f, 0.5f, 0.6666667f, 0x1.fffffep-1f}) {
    const AliasTable::Pick pick = table.sample(u);
    EXPECT_LT(pick.index, 3u);
    EXPECT_GT(pick.pmf, 0.0f);
    EXPECT_LT(pick.remapped_u, 1.0f);
  }
}

TEST(AliasTable, NoWeightMakesAnEmptyTable) {
  EXPECT_TRUE(AliasTable(std::vector<float>{}).empty());
  EXPECT_TRUE(AliasTable(std::vector<float>{0.0f, 0.0f}).empty());
  EXPECT_THROW(AliasTable(std::vector<float>{1.0f, -1.0f}), std::invalid_argument);
}

}  // namespace alias_table_test
}  // namespace rtpro
