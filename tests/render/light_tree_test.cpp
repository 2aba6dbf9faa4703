// The light tree: its pmf is a distribution at every point (sums to 1 over the lights it holds),
// sample() picks each light as often as pmf() says, lights that cannot reach a point are never
// picked there, and it prefers the lights near the point.
#include "light_tree.h"

#include "bsdf_test_support.h"
#include "scattered_lights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

namespace rtpro {
namespace light_tree_test {

using test::Uniforms;

// scattered_lights.h's lights, every fourth without a position.
std::vector<std::optional<LightBounds>> scattered_lights(int count, std::uint64_t seed) {
  Uniforms u(seed);
  return test::scattered_lights(count, u, true);
}

// The pmf of every light, plus the chance that no light is picked (where every light of a
// subtree faces away from the point, the walk stops: those lights send nothing there), is 1.
TEST(LightTree, PmfIsADistributionAtRandomPoints) {
  const auto lights = scattered_lights(1000, 7);
  const LightTree tree(lights);
  ASSERT_FALSE(tree.empty());
  Uniforms u(9);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 p(30.0f * u.next() - 15.0f, 14.0f * u.next() - 2.0f, 30.0f * u.next() - 15.0f);
    double sum = 0.0;
    for (std::uint32_t i = 0; i < lights.size(); ++i) {
      const float pmf = tree.pmf(p, i);
      if (!lights[i]) {
        EXPECT_EQ(pmf, 0.0f);
      }
      sum += pmf;
    }
    constexpr int kPicks = 20000;
    int none = 0;
    for (int k = 0; k < kPicks; ++k) none += !tree.sample(p, (k + 0.5f) / kPicks);
    EXPECT_LE(sum, 1.0 + 1e-5);
    EXPECT_NEAR(sum + double(none) / kPicks, 1.0, 2e-4) << "at " << p.x << " " << p.y << " " << p.z;
  }
}

TEST(LightTree, SamplesFollowThePmfAndTheReturnedPmfIsPmf) {
  const auto lights = scattered_lights(40, 3);
  const LightTree tree(lights);
  const Vec3 p(1.0f, 2.0f, -3.0f);
  std::vector<int> counts(lights.size(), 0);
  constexpr int kSamples = 400000;
  for (int i = 0; i < kSamples; ++i) {
    const float u = (static_cast<float>(i) + 0.5f) / kSamples;
    const std::optional<LightTree::Pick> pick = tree.sample(p, u);
    if (!pick) continue;
    ASSERT_LT(pick->light, lights.size());
    EXPECT_EQ(pick->pmf, tree.pmf(p, pick->light));
    ++counts[pick->light];
  }
  for (std::uint32_t i = 0; i < lights.size(); ++i) {
    const double pmf = tree.pmf(p, i);
    EXPECT_NEAR(counts[i] / double(kSamples), pmf, 1e-4 + 1e-3 * pmf) << "light " << i;
  }
}

TEST(LightTree, NeverPicksALightFacingAway) {
  // Two one-sided quads, each facing away from the other's side: at a point in front of one only
  // it can be picked.
  BBox left, right;
  left.extend(Vec3(-5, 0, 0));
  left.extend(Vec3(-4, 1, 1));
  right.extend(Vec3(4, 0, 0));
  right.extend(Vec3(5, 1, 1));
  const std::vector<std::optional<LightBounds>> lights{LightBounds{left, Vec3(-1, 0, 0), 1.0f, 1.0f, 0.0f, false},
                                                       LightBounds{right, Vec3(1, 0, 0), 1.0f, 1.0f, 0.0f, false}};
  const LightTree tree(lights);
  EXPECT_EQ(tree.pmf(Vec3(10, 0.5f, 0.5f), 0), 0.0f);
  EXPECT_EQ(tree.pmf(Vec3(10, 0.5f, 0.5f), 1), 1.0f);
  EXPECT_EQ(tree.pmf(Vec3(-10, 0.5f, 0.5f), 0), 1.0f);
  // Between them, behind both: nothing.
  EXPECT_FALSE(tree.sample(Vec3(0, 0.5f, 0.5f), 0.3f));
}

TEST(LightTree, PrefersTheNearLightOfEqualPower) {
  std::vector<std::optional<LightBounds>> lights;
  for (int i = 0; i < 64; ++i) {
    BBox b;
    b.extend(Vec3(float(i), 0, 0));
    lights.push_back(LightBounds{b, Vec3(0, 0, 1), 1.0f, -1.0f, 0.0f, false});
  }
  const LightTree tree(lights);
  const Vec3 p(10.0f, 0.5f, 0.0f);
  EXPECT_GT(tree.pmf(p, 10), 10.0f * tree.pmf(p, 60));
  EXPECT_GT(tree.pmf(p, 10), 1.0f / 64.0f);
}

TEST(LightTree, LightsOfZeroPowerOrWithoutPositionAreLeftOut) {
  BBox b;
  b.extend(Vec3(0.0f));
  const std::vector<std::optional<LightBounds>> lights{std::nullopt,
                                                       LightBounds{b, Vec3(0, 0, 1), 0.0f, -1.0f, 0.0f, false},
                                                       LightBounds{b, Vec3(0, 0, 1), 2.0f, -1.0f, 0.0f, false}};
  const LightTree tree(lights);
  EXPECT_EQ(tree.node_count(), 1u);
  EXPECT_EQ(tree.power(), 2.0f);
  EXPECT_EQ(tree.pmf(Vec3(1, 1, 1), 2), 1.0f);
  EXPECT_EQ(tree.pmf(Vec3(1, 1, 1), 1), 0.0f);
  EXPECT_TRUE(LightTree(std::vector<std::optional<LightBounds>>{std::nullopt}).empty());
}

TEST(LightTree, ManyLightsAtOnePointStillFormABalancedTree) {
  BBox b;
  b.extend(Vec3(1.0f));
  const std::vector<std::optional<LightBounds>> lights(5000, LightBounds{b, Vec3(0, 0, 1), 1.0f, -1.0f, 0.0f, false});
  const LightTree tree(lights);
  double sum = 0.0;
  for (std::uint32_t i = 0; i < lights.size(); ++i) sum += tree.pmf(Vec3(3, 3, 3), i);
  EXPECT_NEAR(sum, 1.0, 1e-4);
  EXPECT_NEAR(tree.pmf(Vec3(3, 3, 3), 17), 1.0 / 5000.0, 1e-6);
}

}  // namespace light_tree_test
}  // namespace rtpro
