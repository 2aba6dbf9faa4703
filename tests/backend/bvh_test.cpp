// The native backend's BVH builder: parallel over subtrees and over the binning of large ranges,
// and still the very tree the single-threaded builder makes, at any thread count.
#include "bvh.h"

#include "test_scenes.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cstdint>
#include <cstring>
#include <span>
#include <string>

namespace rtpro {
namespace bvh_test {

// Large enough that the builder splits subtrees across tasks and bins ranges in parallel (both
// thresholds are far below 100,000 primitives), with a stack of coincident spheres that SAH cannot
// separate and a prototype that is itself large.
RenderScene large_scene() {
  RenderScene scene = test::random_mixed_scene(21, 30000, 90000, 12);
  scene.top.geometries.emplace_back(SphereSet{std::vector<Sphere>(20000, Sphere{{1, 2, 3}, 0.5f, 0})});
  return scene;
}

// FNV-1a over every byte of the nodes and references.
std::uint64_t fingerprint(const Bvh& bvh) {
  std::uint64_t hash = 1469598103934665603ull;
  auto add = [&hash](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
  };
  add(bvh.nodes.data(), bvh.nodes.size() * sizeof(BvhNode));
  add(bvh.refs.data(), bvh.refs.size() * sizeof(PrimitiveRef));
  return hash;
}

void expect_same_tree(const Bvh& expected, const Bvh& actual) {
  ASSERT_EQ(expected.nodes.size(), actual.nodes.size());
  ASSERT_EQ(expected.refs.size(), actual.refs.size());
  for (std::size_t i = 0; i < expected.nodes.size(); ++i)
    ASSERT_EQ(std::memcmp(&expected.nodes[i], &actual.nodes[i], sizeof(BvhNode)), 0) << "node " << i;
  EXPECT_EQ(std::memcmp(expected.refs.data(), actual.refs.data(), expected.refs.size() * sizeof(PrimitiveRef)), 0);
}

Bvh build_with_threads(int threads, const Group& group, std::span<const BBox> prototype_bounds) {
  tbb::task_arena arena(threads);
  Bvh bvh;
  arena.execute([&] { bvh = build_bvh(group, prototype_bounds); });
  return bvh;
}

TEST(Bvh, ParallelBuildIsTheSequentialTreeAtOneAndTwoThreads) {
  const RenderScene scene = large_scene();
  const auto bounds = scene.prototype_bounds();
  for (const Group* group : {&scene.top, &scene.prototypes[0]}) {
    const std::span<const BBox> used = group == &scene.top ? std::span<const BBox>(bounds) : std::span<const BBox>();
    const Bvh sequential = build_bvh(*group, used, BvhBuildMode::kSequential);
    for (int threads : {1, 2}) {
      SCOPED_TRACE(std::to_string(threads) + " threads");
      expect_same_tree(sequential, build_with_threads(threads, *group, used));
    }
  }
}

// Recorded from the builder before it was parallelised (single-threaded, one std::partition per
// node); a change here is a different tree, not a faster build of the same one.
TEST(Bvh, IsTheTreeTheSingleThreadedBuilderMade) {
  const RenderScene scene = large_scene();
  const Bvh top = build_bvh(scene.top, scene.prototype_bounds());
  const Bvh prototype = build_bvh(scene.prototypes[0], {});
  EXPECT_EQ(top.nodes.size(), 120307u);
  EXPECT_EQ(fingerprint(top), 5902508181359816260ull);
  EXPECT_EQ(prototype.nodes.size(), 30215u);
  EXPECT_EQ(fingerprint(prototype), 8099507034210695486ull);
}

}  // namespace bvh_test
}  // namespace rtpro
