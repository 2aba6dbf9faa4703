#pragma once
// The native backend's bounding volume hierarchy: binned SAH over the primitives of one group
// (spheres, triangles and instances alike), stored in 32-byte nodes with sibling pairs.
#include "rtpro/core/huge_page_buffer.h"
#include "rtpro/core/bbox.h"
#include "rtpro/scene/render_scene.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

struct BvhNode {
  BBox bounds;
  // Leaf: first primitive reference and count > 0. Interior: count == 0, children at `index`
  // (left, lower coordinates) and `index + 1`, `axis` the split axis (for front-to-back order).
  std::uint32_t index;
  std::uint16_t count;
  std::uint16_t axis;
  bool is_leaf() const { return count > 0; }
};
static_assert(sizeof(BvhNode) == 32);

// A box moving linearly over the shutter (ray time t in [0, 1]: at_open + t · (at_close −
// at_open)), which holds its primitives where they are at every t: a node's box for rays with a
// time, tighter than the box of the whole motion where things move far.
struct LinearBounds {
  BBox at_open;
  BBox at_close;
  // The box at ray time `time`, exactly at_open where nothing moves.
  BBox at(float time) const {
    const auto lerp = [time](const Vec3& a, const Vec3& b) {
      return Vec3(a.x + time * (b.x - a.x), a.y + time * (b.y - a.y), a.z + time * (b.z - a.z));
    };
    return {lerp(at_open.lower, at_close.lower), lerp(at_open.upper, at_close.upper)};
  }
};

// A node of a BVH whose group moves: its linear bounds and the BvhNode's index, count and axis
// in one cache line, the only line a ray with a time reads of a node.
struct alignas(64) MotionNode {
  LinearBounds bounds;
  std::uint32_t index;
  std::uint16_t count;
  std::uint16_t axis;
};
static_assert(sizeof(MotionNode) == 64);

struct PrimitiveRef {
  std::uint32_t geom;
  std::uint32_t prim;
};

struct Bvh {
  std::vector<BvhNode, HugePageAllocator<BvhNode>> nodes;
  std::vector<PrimitiveRef, HugePageAllocator<PrimitiveRef>> refs;
  // Per node, where something in the group moves during the shutter (else empty): the node with
  // its linear bounds, which rays with a time test instead of `bounds` (the box of the whole
  // motion).
  std::vector<MotionNode, HugePageAllocator<MotionNode>> motion_nodes;
  std::size_t memory_bytes() const {
    return nodes.capacity() * sizeof(BvhNode) + refs.capacity() * sizeof(PrimitiveRef) +
           motion_nodes.capacity() * sizeof(MotionNode);
  }
};

inline constexpr int kBvhMaxDepth = 128;

// kParallel uses the calling TBB arena's threads; kSequential builds on the calling thread alone
// and is the reference the parallel build must equal.
enum class BvhBuildMode { kParallel, kSequential };

// Deterministic: the same group always gives the same tree, node for node and byte for byte,
// whatever the mode and the number of threads.
Bvh build_bvh(const Group& group, std::span<const BBox> prototype_bounds, BvhBuildMode mode = BvhBuildMode::kParallel);

}  // namespace rtpro
