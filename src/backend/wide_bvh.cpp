#include "wide_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rtpro {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

BBox widened(const BBox& b) {
  return {{std::nextafter(b.lower.x, -kInfinity), std::nextafter(b.lower.y, -kInfinity),
           std::nextafter(b.lower.z, -kInfinity)},
          {std::nextafter(b.upper.x, kInfinity), std::nextafter(b.upper.y, kInfinity),
           std::nextafter(b.upper.z, kInfinity)}};
}

// A binary tree whose leaves are single primitives: the input tree with each multi-primitive leaf
// split further (at the median along its primitives' widest centroid axis).
struct BinaryNode {
  BBox bounds;
  std::uint32_t left = 0, right = 0;  // children, when interior
  std::uint32_t ref = WideBvhNode::kEmpty;  // primitive index in refs, when a leaf
  bool is_leaf() const { return ref != WideBvhNode::kEmpty; }
};

class Collapser {
 public:
  Collapser(const Bvh& bvh, const Group& group, std::span<const BBox> prototype_bounds)
      : bvh_(bvh), group_(group), prototype_bounds_(prototype_bounds) {}

  WideBvh collapse() {
    WideBvh wide;
    wide.refs = bvh_.refs;
    if (bvh_.nodes.empty()) return wide;
    const std::uint32_t root = binary_from(0);
    wide.nodes.emplace_back();
    fill(wide, 0, root);
    return wide;
  }

 private:
  BBox primitive_box(std::uint32_t ref) const {
    const PrimitiveRef& r = bvh_.refs[ref];
    return widened(group_.primitive_bounds(r.geom, r.prim, prototype_bounds_));
  }

  std::uint32_t add(const BinaryNode& node) {
    binary_.push_back(node);
    return static_cast<std::uint32_t>(binary_.size() - 1);
  }

  std::uint32_t binary_from(std::uint32_t index) {
    const BvhNode& node = bvh_.nodes[index];
    if (!node.is_leaf()) {
      const std::uint32_t left = binary_from(node.index);
      const std::uint32_t right = binary_from(node.index + 1);
      return add({merge(binary_[left].bounds, binary_[right].bounds), left, right});
    }
    std::vector<std::uint32_t> refs(node.count);
    for (std::uint32_t i = 0; i < node.count; ++i) refs[i] = node.index + i;
    return split_leaf(refs);
  }

  std::uint32_t split_leaf(std::span<std::uint32_t> refs) {
    if (refs.size() == 1) return add({primitive_box(refs[0]), 0, 0, refs[0]});
    BBox centroids;
    for (std::uint32_t r : refs) centroids.extend(primitive_box(r).center());
    const int axis = centroids.largest_axis();
    const std::size_t mid = refs.size() / 2;
    std::nth_element(refs.begin(), refs.begin() + static_cast<std::ptrdiff_t>(mid), refs.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                       const float ca = primitive_box(a).center()[axis], cb = primitive_box(b).center()[axis];
                       return ca != cb ? ca < cb : a < b;
                     });
    const std::uint32_t left = split_leaf(refs.subspan(0, mid));
    const std::uint32_t right = split_leaf(refs.subspan(mid));
    return add({merge(binary_[left].bounds, binary_[right].bounds), left, right});
  }

  // Writes wide node `slot` from binary node `index`: its up-to-four children are found by
  // opening, while there is room, the interior candidate with the largest surface area.
  void fill(WideBvh& wide, std::uint32_t slot, std::uint32_t index) {
    std::vector<std::uint32_t> children;
    if (binary_[index].is_leaf()) {
      children.push_back(index);
    } else {
      children = {binary_[index].left, binary_[index].right};
    }
    while (children.size() < 4) {
      int best = -1;
      float best_area = -1.0f;
      for (std::size_t i = 0; i < children.size(); ++i) {
        const BinaryNode& c = binary_[children[i]];
        if (!c.is_leaf() && c.bounds.surface_area() > best_area) {
          best = static_cast<int>(i);
          best_area = c.bounds.surface_area();
        }
      }
      if (best < 0) break;
      const BinaryNode opened = binary_[children[static_cast<std::size_t>(best)]];
      children[static_cast<std::size_t>(best)] = opened.left;
      children.insert(children.begin() + best + 1, opened.right);
    }

    WideBvhNode node;
    for (int c = 0; c < 4; ++c) {
      for (int axis = 0; axis < 3; ++axis) {
        node.bounds[axis][0][c] = kInfinity;
        node.bounds[axis][1][c] = -kInfinity;
      }
      node.child[c] = WideBvhNode::kEmpty;
    }
    std::vector<std::pair<int, std::uint32_t>> interior;  // (slot in node, binary index)
    for (std::size_t c = 0; c < children.size(); ++c) {
      const BinaryNode& child = binary_[children[c]];
      for (int axis = 0; axis < 3; ++axis) {
        node.bounds[axis][0][c] = child.bounds.lower[axis];
        node.bounds[axis][1][c] = child.bounds.upper[axis];
      }
      if (child.is_leaf()) {
        node.child[c] = WideBvhNode::kLeafBit | child.ref;
      } else {
        node.child[c] = static_cast<std::uint32_t>(wide.nodes.size());
        wide.nodes.emplace_back();
        interior.emplace_back(static_cast<int>(c), children[c]);
      }
    }
    wide.nodes[slot] = node;
    for (const auto& [c, binary_index] : interior) fill(wide, wide.nodes[slot].child[c], binary_index);
  }

  const Bvh& bvh_;
  const Group& group_;
  std::span<const BBox> prototype_bounds_;
  std::vector<BinaryNode> binary_;
};

}  // namespace

WideBvh make_wide_bvh(const Bvh& bvh, const Group& group, std::span<const BBox> prototype_bounds) {
  return Collapser(bvh, group, prototype_bounds).collapse();
}

}  // namespace rtpro
