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

struct PrimitiveRef {
  std::uint32_t geom;
  std::uint32_t prim;
};

struct Bvh {
  std::vector<BvhNode, HugePageAllocator<BvhNode>> nodes;
  std::vector<PrimitiveRef, HugePageAllocator<PrimitiveRef>> refs;
  std::size_t memory_bytes() const {
    return nodes.capacity() * sizeof(BvhNode) + refs.capacity() * sizeof(PrimitiveRef);
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
