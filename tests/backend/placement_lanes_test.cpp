// A moving instance's placements, four lanes at a time, against placement_at one at a time: the
// same matrices to the bit and the same verdict on singular ones, so a packet's lanes enter the
// instance exactly where single rays do.
#include "placement_lanes.h"

#include "rtpro/core/transform.h"
#include "rtpro/scene/render_scene.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <optional>
#include <random>
#include <vector>

namespace rtpro {
namespace {

Affine random_affine(std::mt19937& rng) {
  std::uniform_real_distribution<float> value(-3.0f, 3.0f);
  Affine a;
  for (auto& row : a.m)
    for (float& v : row) v = value(rng);
  return a;
}

Instance moving_instance(std::vector<Affine> steps) {
  Instance instance{0, steps.front(), steps.front()};
  instance.object_to_world_steps = std::move(steps);
  return instance;
}

bool same_bits(const Affine& a, const Affine& b) { return std::memcmp(&a, &b, sizeof(Affine)) == 0; }

void expect_lanes_match_placement_at(const Instance& instance, const float* times, unsigned count) {
  Affine lanes[kPlacementLanes];
  const unsigned placed = world_to_object_lanes(instance, times, count, lanes);
  EXPECT_EQ(placed >> count, 0u);
  for (unsigned k = 0; k < count; ++k) {
    const std::optional<InstancePlacement> one = placement_at(instance, times[k]);
    ASSERT_EQ(one.has_value(), (placed >> k & 1u) != 0) << "lane " << k << " at time " << times[k];
    if (one) {
      EXPECT_TRUE(same_bits(one->world_to_object, lanes[k])) << "lane " << k << " at time " << times[k];
    }
  }
}

class PlacementLanes : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "needs AVX2, as the native packets that use it";
  }
};

TEST_F(PlacementLanes, RandomMotionsGiveEachLanePlacementAtsMatrixToTheBit) {
  std::mt19937 rng(20261129);
  std::uniform_real_distribution<float> time(0.0f, 1.0f);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<Affine> steps;
    const int step_count = 2 + trial % 4;
    for (int s = 0; s < step_count; ++s) steps.push_back(random_affine(rng));
    const Instance instance = moving_instance(std::move(steps));
    const float times[kPlacementLanes] = {time(rng), time(rng), trial % 3 == 0 ? 1.0f : time(rng), 0.0f};
    expect_lanes_match_placement_at(instance, times, 1 + static_cast<unsigned>(trial) % kPlacementLanes);
  }
}

TEST_F(PlacementLanes, SingularAndOverflowingPlacementsAreRefusedAsPlacementAtRefusesThem) {
  const Affine flat = Affine::scale({1.0f, 0.0f, 1.0f});             // singular at every time
  const Affine turned = Affine::rotate({0.0f, 1.0f, 0.0f}, 180.0f);  // halfway to the identity: diag(0, 1, 0)
  const Affine tiny = Affine::scale({1e-6f, 1e-6f, 1e-6f});          // regular: the test is relative to its scale
  Affine overflowing = Affine::scale({1e-30f, 1e-30f, 1e-30f});      // its inverse moves by -1e60: not a float
  overflowing.m[0][3] = 1e30f;
  const Instance instances[] = {moving_instance({flat, flat}), moving_instance({turned, Affine{}}),
                                moving_instance({tiny, Affine{}}), moving_instance({overflowing, overflowing})};
  const float times[kPlacementLanes] = {0.0f, 0.5f, 0.25f, 1.0f};
  for (const Instance& instance : instances) expect_lanes_match_placement_at(instance, times, kPlacementLanes);
  Affine lanes[kPlacementLanes];
  EXPECT_EQ(world_to_object_lanes(instances[0], times, kPlacementLanes, lanes), 0u);
  EXPECT_EQ(world_to_object_lanes(instances[1], times, kPlacementLanes, lanes), 0b1101u);  // not at t = 0.5
  EXPECT_EQ(world_to_object_lanes(instances[2], times, kPlacementLanes, lanes), 0b1111u);
  EXPECT_EQ(world_to_object_lanes(instances[3], times, kPlacementLanes, lanes), 0u);
}

TEST_F(PlacementLanes, NonFiniteStepsAreRefused) {
  Affine broken;
  broken.m[1][2] = __builtin_nanf("");
  const Instance instance = moving_instance({broken, Affine{}});
  const float times[kPlacementLanes] = {0.0f, 0.3f, 0.7f, 1.0f};
  expect_lanes_match_placement_at(instance, times, kPlacementLanes);
}

}  // namespace
}  // namespace rtpro
