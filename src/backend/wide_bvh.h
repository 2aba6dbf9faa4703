#pragma once
// The native backend's traversal layout: the binary SAH tree of bvh.h collapsed into nodes of up
// to four children whose boxes are stored structure-of-arrays, so one SSE instruction sequence tests
// a ray against all four. Leaves hold exactly one primitive each, with the primitive's own box
// (rounded one ulp outwards): a ray pays for the double-precision sphere or triangle test only when
// it enters that primitive's box, and the four boxes of a node are tested at once.
#include "bvh.h"
#include "rtpro/core/bbox.h"
#include "rtpro/scene/render_scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

struct alignas(16) WideBvhNode {
  static constexpr std::uint32_t kEmpty = ~0u;
  static constexpr std::uint32_t kLeafBit = 1u << 31;

  // bounds[axis][0] lower and bounds[axis][1] upper bounds of the four children along axis.
  // Empty slots have lower +inf and upper −inf, so no ray enters them.
  float bounds[3][2][4];
  // Interior child: its node index. Leaf child: kLeafBit | its primitive's index in `refs`.
  std::uint32_t child[4];
};
static_assert(sizeof(WideBvhNode) == 112);

struct WideBvh {
  std::vector<WideBvhNode> nodes;  // nodes[0] is the root (when there is any primitive)
  std::vector<PrimitiveRef> refs;
  std::size_t memory_bytes() const {
    return nodes.capacity() * sizeof(WideBvhNode) + refs.capacity() * sizeof(PrimitiveRef);
  }
};

// Deterministic for a given tree.
WideBvh make_wide_bvh(const Bvh& bvh, const Group& group, std::span<const BBox> prototype_bounds);

}  // namespace rtpro
