// A picker of one light picks it, with probability 1, from every point and for every u (its pick
// is made once), and a picker of two lights still picks by the point and u; a light left out of a
// picker's members is never picked.
#include "light_picker.h"

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <vector>

namespace rtpro {
namespace light_picker_test {

LightBounds point_bounds(const Vec3& position, float power) {
  LightBounds b;
  b.bounds.extend(position);
  b.phi = power;
  b.cos_theta_o = -1.0f;  // shines every way
  return b;
}

// Lights of a set: 0 a point light at the origin, 1 a point light far along x, 2 a directional
// light (no position).
const std::vector<float> kPower{4.0f, 4.0f, 2.0f};
const std::vector<std::optional<LightBounds>> kBounds{point_bounds(Vec3(0.0f), 4.0f),
                                                      point_bounds(Vec3(100.0f, 0.0f, 0.0f), 4.0f), std::nullopt};

TEST(LightPicker, OneLightIsPickedWithCertaintyFromEveryPoint) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> coordinate(-200.0f, 200.0f), unit(0.0f, 1.0f);
  for (const LightSamplerKind kind : {LightSamplerKind::kTree, LightSamplerKind::kPower})
    for (const std::uint32_t light : {0u, 1u, 2u}) {
      const std::vector<std::uint32_t> members{light};
      const LightPicker picker(kind, members, kPower, kBounds);
      ASSERT_FALSE(picker.empty());
      for (int i = 0; i < 1000; ++i) {
        const Vec3 point{coordinate(rng), coordinate(rng), coordinate(rng)};
        const std::optional<LightPicker::Pick> pick = picker.pick(point, unit(rng) * 0x1.fffffep-1f);
        ASSERT_TRUE(pick);
        EXPECT_EQ(pick->light, light);
        EXPECT_EQ(pick->pmf, 1.0f);
        EXPECT_EQ(picker.probability(light, point), 1.0f);
      }
    }
}

TEST(LightPicker, TwoLightsArePickedByThePointAndU) {
  const std::vector<std::uint32_t> members{0, 1};
  const LightPicker tree(LightSamplerKind::kTree, members, kPower, kBounds);
  // Near light 0 the tree prefers it, near light 1 the other; u chooses between them.
  const Vec3 near_first(1.0f, 0.0f, 0.0f), near_second(99.0f, 0.0f, 0.0f);
  EXPECT_EQ(tree.pick(near_first, 0.01f)->light, 0u);
  EXPECT_EQ(tree.pick(near_second, 0.99f)->light, 1u);
  EXPECT_GT(tree.pick(near_first, 0.01f)->pmf, 0.5f);
  EXPECT_LT(tree.pick(near_first, 0.01f)->pmf, 1.0f);
  const LightPicker power(LightSamplerKind::kPower, members, kPower, kBounds);
  EXPECT_NE(power.pick(near_first, 0.25f)->light, power.pick(near_first, 0.75f)->light);
  EXPECT_EQ(power.pick(near_first, 0.25f)->pmf, 0.5f);
}

// The tree picker gives the lights without a position one share each and the tree one, whatever
// their power: a directional light 1,000 times the point lights' power is still picked half the
// time, and the probabilities pick() returns sum to 1 with probability() agreeing.
TEST(LightPicker, TreeGivesEachLightWithoutAPositionOneShareWhateverItsPower) {
  for (const float directional_power : {1e-3f, 2.0f, 4e3f}) {
    const std::vector<float> power{4.0f, 4.0f, directional_power};
    const std::vector<std::uint32_t> members{0, 1, 2};
    const LightPicker picker(LightSamplerKind::kTree, members, power, kBounds);
    const Vec3 point(1.0f, 0.0f, 0.0f);
    EXPECT_EQ(picker.probability(2, point), 0.5f) << directional_power;
    EXPECT_NEAR(picker.probability(0, point) + picker.probability(1, point), 0.5f, 1e-6f) << directional_power;
    int directional = 0;
    constexpr int kPicks = 1000;
    for (int i = 0; i < kPicks; ++i) {
      const std::optional<LightPicker::Pick> pick = picker.pick(point, (i + 0.5f) / kPicks);
      ASSERT_TRUE(pick);
      EXPECT_EQ(pick->pmf, picker.probability(pick->light, point));
      directional += pick->light == 2u;
    }
    EXPECT_EQ(directional, kPicks / 2) << directional_power;
  }
  // Without lights in the tree, the directional light is all there is.
  const std::vector<std::uint32_t> alone{2};
  EXPECT_EQ(LightPicker(LightSamplerKind::kTree, alone, kPower, kBounds).probability(2, Vec3(0.0f)), 1.0f);
}

TEST(LightPicker, ALightWithoutPowerLeavesThePickerEmpty) {
  const std::vector<float> no_power{0.0f};
  const std::vector<std::optional<LightBounds>> bounds{point_bounds(Vec3(0.0f), 0.0f)};
  const std::vector<std::uint32_t> members{0};
  EXPECT_TRUE(LightPicker(LightSamplerKind::kTree, members, no_power, bounds).empty());
  EXPECT_TRUE(LightPicker(LightSamplerKind::kPower, members, no_power, bounds).empty());
}

}  // namespace light_picker_test
}  // namespace rtpro
