#include "bvh.h"

#include "box4.h"
#include "bvh_binning.h"
#include "rtpro/core/huge_page_buffer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cstdint>
#include <memory>

namespace rtpro {

namespace {

using bvh_build::BuildPrimitive;
using bvh_build::kChunk;
using bvh_build::kParallelRange;
using bvh_build::RangeBounds;

constexpr int kMaxLeafSize = 8;
// Below this depth limit the builder may follow SAH freely; past it, it splits at the median so
// that the tree depth (and the traversal stack) stays bounded on adversarial input.
constexpr int kSahDepthLimit = kBvhMaxDepth - 32;
// Subtrees of at most this many primitives are built by one task; larger ones split their two
// children across tasks.
constexpr std::uint32_t kParallelSubtree = 4096;

// What one node does with its range: a leaf when mid == begin, else children [begin, mid) and
// [mid, end) split along `axis`.
struct Decision {
  BBox bounds;
  std::uint32_t mid;
  int axis;
};

BvhNode relocated(BvhNode node, std::uint32_t shift) {
  if (!node.is_leaf()) node.index += shift;
  return node;
}

// Parallel and still deterministic: the tree (nodes, their order, the primitive order) is the one
// the single-threaded builder makes, whatever the thread count.
// - Bounds and bins are minima, maxima and integer counts, reduced over chunks in index order:
//   exact, so no result depends on how the work was divided.
// - Subtrees own disjoint primitive ranges, so partitioning them concurrently leaves the same
//   array as partitioning them one after the other.
// - Node indices come from one pass at the end that hands out positions in the order of the
//   single-threaded depth-first build (see place()).
class BvhBuilder {
 public:
  BvhBuilder(HugePageBuffer<BuildPrimitive> primitives, std::uint32_t count, bool parallel)
      : prims_(std::move(primitives)), count_(count), parallel_(parallel), scratch_(2 * std::size_t{count}) {}

  Bvh build() {
    Bvh bvh;
    if (count_ == 0) return bvh;
    const std::uint32_t count = count_;
    if (!parallel_) {
      const std::uint32_t size = build_sequential(scratch_.get(), 0, count, 0);
      bvh.nodes.assign(scratch_.get(), scratch_.get() + size);
    } else {
      Part root;
      build_part(root, 0, count, 0);
      bvh.nodes.resize(root.size);
      std::vector<Copy> copies;
      std::uint32_t next = 1;
      place(root, 0, next, bvh.nodes, copies);
      tbb::parallel_for(std::size_t{0}, copies.size(), [&](std::size_t i) { copy_part(copies[i], bvh.nodes); });
    }
    bvh.refs.resize(count);
    for_range(0, count, [&](std::uint32_t begin, std::uint32_t end) {
      for (std::uint32_t i = begin; i < end; ++i) bvh.refs[i] = prims_[i].ref();
    });
    return bvh;
  }

 private:
  // A subtree of the parallel phase: either an interior node whose children were built by two
  // tasks, or a subtree built by one task into the scratch array from 2 * begin (its root first,
  // then its descendants as build_sequential lays them out, indices counted from the root; a tree
  // over n primitives has at most 2n - 1 nodes, so subtrees never overlap).
  struct Part {
    BvhNode node{};
    std::unique_ptr<Part> left, right;
    std::uint32_t first = 0;  // the root's place in scratch_
    std::uint32_t size = 0;   // nodes in the subtree
  };

  struct Copy {
    std::uint32_t first, size;  // in scratch_
    std::uint32_t slot;         // where the subtree's root goes
    std::uint32_t base;         // where its descendants start
  };

  // The single-threaded builder: depth first, both children of a node allocated together, the
  // left subtree finished before the right one starts. Writes the subtree to `nodes`, which has
  // room for 2 * (end - begin) - 1 (the most a tree over that many primitives has), and returns
  // its node count.
  std::uint32_t build_sequential(BvhNode* nodes, std::uint32_t begin, std::uint32_t end, int depth) {
    std::uint32_t size = 1;
    struct Task {
      std::uint32_t node, begin, end;
      int depth;
    };
    std::vector<Task> stack;
    stack.push_back({0, begin, end, depth});
    while (!stack.empty()) {
      const Task task = stack.back();
      stack.pop_back();
      const Decision d = decide(task.begin, task.end, task.depth);
      if (d.mid == task.begin) {
        nodes[task.node] = leaf(d.bounds, task.begin, task.end);
        continue;
      }
      // Siblings are allocated as a pair, so one index finds both children.
      const std::uint32_t left = size;
      size += 2;
      nodes[task.node] = {d.bounds, left, 0, static_cast<std::uint16_t>(d.axis)};
      stack.push_back({left + 1, d.mid, task.end, task.depth + 1});
      stack.push_back({left, task.begin, d.mid, task.depth + 1});
    }
    return size;
  }

  void build_part(Part& part, std::uint32_t begin, std::uint32_t end, int depth) {
    if (end - begin <= kParallelSubtree) {
      part.first = 2 * begin;
      part.size = build_sequential(scratch_.get() + part.first, begin, end, depth);
      return;
    }
    const Decision d = decide(begin, end, depth);
    if (d.mid == begin) {
      part.first = 2 * begin;
      scratch_[part.first] = leaf(d.bounds, begin, end);
      part.size = 1;
      return;
    }
    part.node = {d.bounds, 0, 0, static_cast<std::uint16_t>(d.axis)};
    part.left = std::make_unique<Part>();
    part.right = std::make_unique<Part>();
    tbb::parallel_invoke([&] { build_part(*part.left, begin, d.mid, depth + 1); },
                         [&] { build_part(*part.right, d.mid, end, depth + 1); });
    part.size = 1 + part.left->size + part.right->size;
  }

  // Gives `part`'s root the index `slot` and its descendants the positions build_sequential would
  // have given them: the children's pair next, then all of the left subtree, then the right.
  template <typename Nodes>
  static void place(const Part& part, std::uint32_t slot, std::uint32_t& next, Nodes& nodes,
                    std::vector<Copy>& copies) {
    if (!part.left) {
      copies.push_back({part.first, part.size, slot, next});
      next += part.size - 1;
      return;
    }
    const std::uint32_t left = next;
    next += 2;
    nodes[slot] = part.node;
    nodes[slot].index = left;
    place(*part.left, left, next, nodes, copies);
    place(*part.right, left + 1, next, nodes, copies);
  }

  // Local index k > 0 of a part built in one task goes to base + k - 1.
  template <typename Nodes>
  void copy_part(const Copy& copy, Nodes& nodes) const {
    const BvhNode* local = scratch_.get() + copy.first;
    const std::uint32_t shift = copy.base - 1;
    nodes[copy.slot] = relocated(local[0], shift);
    for (std::uint32_t k = 1; k < copy.size; ++k) nodes[copy.base + k - 1] = relocated(local[k], shift);
  }

  static BvhNode leaf(const BBox& bounds, std::uint32_t begin, std::uint32_t end) {
    return {bounds, begin, static_cast<std::uint16_t>(end - begin), 0};
  }

  // Calls body(chunk_begin, chunk_end) over [begin, end): in parallel chunks for a large range.
  template <typename Body>
  void for_range(std::uint32_t begin, std::uint32_t end, Body&& body) const {
    if (!parallel_ || end - begin < kParallelRange) return body(begin, end);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(begin, end, kChunk),
                      [&](const tbb::blocked_range<std::uint32_t>& r) { body(r.begin(), r.end()); });
  }

  // Folds fold(value, chunk_begin, chunk_end) over [begin, end) and joins the chunks' values in
  // index order with join(left, right), on fixed chunk boundaries for a large range.
  template <typename Value, typename Fold, typename Join>
  Value reduce_range(std::uint32_t begin, std::uint32_t end, Fold&& fold, Join&& join) const {
    if (!parallel_ || end - begin < kParallelRange) return fold(Value{}, begin, end);
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<std::uint32_t>(begin, end, kChunk), Value{},
        [&](const tbb::blocked_range<std::uint32_t>& r, Value value) { return fold(value, r.begin(), r.end()); }, join,
        tbb::simple_partitioner());
  }

  RangeBounds bounds_of(std::uint32_t begin, std::uint32_t end) const {
    return reduce_range<RangeBounds>(
        begin, end,
        [this](RangeBounds r, std::uint32_t b, std::uint32_t e) {
          Box4 bounds(r.bounds), centroids(r.centroids);
          for (std::uint32_t i = b; i < e; ++i) {
            const BuildPrimitive& p = prims_[i];
            const __m128 lower = bvh_build::lower4(p), upper = bvh_build::upper4(p);
            bounds.extend(lower, upper);
            const __m128 c = bvh_build::centroid4(lower, upper);
            centroids.extend(c, c);
          }
          return RangeBounds{bounds.box(), centroids.box()};
        },
        [](RangeBounds a, const RangeBounds& b) {
          a.bounds.extend(b.bounds);
          a.centroids.extend(b.centroids);
          return a;
        });
  }

  Decision decide(std::uint32_t begin, std::uint32_t end, int depth) {
    const RangeBounds range = bounds_of(begin, end);
    int axis = 0;
    const std::uint32_t mid = choose_partition(begin, end, range, depth, axis);
    return {range.bounds, mid, axis};
  }

  // Returns the split position in [begin, end), or begin to make a leaf; sets `axis` to the
  // axis the primitives were separated along.
  std::uint32_t choose_partition(std::uint32_t begin, std::uint32_t end, const RangeBounds& range, int depth,
                                 int& axis) {
    const BBox& centroids = range.centroids;
    const std::uint32_t count = end - begin;
    if (count <= 2) return begin;
    axis = centroids.largest_axis();
    const float extent = centroids.extent()[axis];
    if (!(extent > 0.0f)) {
      // All centroids coincide: SAH cannot separate them, so split by position in the array.
      return count <= kMaxLeafSize ? begin : begin + count / 2;
    }
    if (depth >= kSahDepthLimit) return median_split(begin, end, axis);

    const bvh_build::Split split = bvh_build::best_sah_split(prims_.get(), begin, end, range, parallel_);
    const float leaf_cost = static_cast<float>(count);
    if (split.axis < 0) return count <= kMaxLeafSize ? begin : median_split(begin, end, axis);
    if (split.cost >= leaf_cost && count <= kMaxLeafSize) return begin;

    axis = split.axis;
    const float lo = centroids.lower[split.axis];
    const float scale = bvh_build::kBinCount / centroids.extent()[split.axis];
    // std::partition, not a parallel one: its exact order of the two sides is part of the tree.
    auto* middle = std::partition(prims_.get() + begin, prims_.get() + end, [&](const BuildPrimitive& p) {
      return bvh_build::bin_of(p.centroid(split.axis), lo, scale) <= split.bin;
    });
    const auto mid = static_cast<std::uint32_t>(middle - prims_.get());
    if (mid == begin || mid == end) return median_split(begin, end, axis);
    return mid;
  }

  std::uint32_t median_split(std::uint32_t begin, std::uint32_t end, int axis) {
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(prims_.get() + begin, prims_.get() + mid, prims_.get() + end,
                     [axis](const BuildPrimitive& a, const BuildPrimitive& b) {
                       const float ca = a.centroid(axis), cb = b.centroid(axis);
                       if (ca != cb) return ca < cb;
                       return a.geom != b.geom ? a.geom < b.geom : a.prim < b.prim;
                     });
    return mid;
  }

  HugePageBuffer<BuildPrimitive> prims_;
  std::uint32_t count_;
  bool parallel_;
  HugePageBuffer<BvhNode> scratch_;  // subtrees as built, before they are laid out
};

// Linear bounds of a primitive moving through `steps` (>= 2) boxes at evenly spaced times: the
// first and last steps' boxes, each face pushed out as far as any middle step pokes past the
// faces' interpolation. Between two steps the primitive lies within their boxes' interpolation,
// so within these; the padding covers float rounding, which differs between these bounds'
// formula (LinearBounds::at) and the shapes' own interpolation (scene/motion.h).
template <typename BoxAt>
LinearBounds linear_bounds(std::uint32_t steps, BoxAt&& box_at) {
  LinearBounds bounds{box_at(0), box_at(steps - 1)};
  for (std::uint32_t i = 1; i + 1 < steps; ++i) {
    const float time = static_cast<float>(i) / static_cast<float>(steps - 1);
    const BBox step = box_at(i);
    const BBox there = bounds.at(time);
    const Vec3 below = min(step.lower - there.lower, Vec3(0.0f));
    const Vec3 above = max(step.upper - there.upper, Vec3(0.0f));
    bounds.at_open = {bounds.at_open.lower + below, bounds.at_open.upper + above};
    bounds.at_close = {bounds.at_close.lower + below, bounds.at_close.upper + above};
  }
  const Vec3 magnitude = max(max(abs(bounds.at_open.lower), abs(bounds.at_open.upper)),
                             max(abs(bounds.at_close.lower), abs(bounds.at_close.upper)));
  const Vec3 pad = magnitude * 0x1p-20f;
  bounds.at_open = {bounds.at_open.lower - pad, bounds.at_open.upper + pad};
  bounds.at_close = {bounds.at_close.lower - pad, bounds.at_close.upper + pad};
  return bounds;
}

// Primitive `p` of geometry `g` as it moves (its box at every time when it keeps still).
LinearBounds primitive_linear_bounds(const Group& group, std::uint32_t g, std::uint32_t p,
                                     std::span<const BBox> prototype_bounds) {
  const std::uint32_t steps = group.motion_step_count(g);
  if (steps == 0) {
    const BBox box = group.primitive_bounds(g, p, prototype_bounds);
    return {box, box};
  }
  return linear_bounds(
      steps, [&](std::uint32_t step) { return group.primitive_bounds_at_step(g, p, step, prototype_bounds); });
}

// Every primitive's bounds, computed in parallel into its place in geometry order; primitives
// with empty bounds (an instance of an empty prototype) are then dropped, keeping the order.
HugePageBuffer<BuildPrimitive> build_primitives(const Group& group, std::span<const BBox> prototype_bounds,
                                                std::uint32_t& count) {
  std::vector<std::size_t> first(group.geometries.size() + 1, 0);
  for (std::uint32_t g = 0; g < group.geometries.size(); ++g) first[g + 1] = first[g] + group.primitive_count(g);
  HugePageBuffer<BuildPrimitive> primitives(first.back());
  std::vector<char> moving(group.geometries.size());
  for (std::uint32_t g = 0; g < group.geometries.size(); ++g) moving[g] = group.motion_step_count(g) > 0;
  tbb::parallel_for(std::uint32_t{0}, static_cast<std::uint32_t>(group.geometries.size()), [&](std::uint32_t g) {
    tbb::parallel_for(
        tbb::blocked_range<std::uint32_t>(0, group.primitive_count(g), kChunk),
        [&](const tbb::blocked_range<std::uint32_t>& r) {
          for (std::uint32_t p = r.begin(); p < r.end(); ++p) {
            // A moving primitive is placed in the tree by its box halfway through the shutter,
            // which rays with a time test (motion_nodes_of) at the time they carry.
            const BBox b = moving[g] ? primitive_linear_bounds(group, g, p, prototype_bounds).at(0.5f)
                                     : group.primitive_bounds(g, p, prototype_bounds);
            primitives[first[g] + p] = {{b.lower.x, b.lower.y, b.lower.z}, g, {b.upper.x, b.upper.y, b.upper.z}, p};
          }
        });
  });
  const auto* end = std::remove_if(primitives.get(), primitives.get() + first.back(),
                                   [](const BuildPrimitive& p) { return p.bounds().empty(); });
  count = static_cast<std::uint32_t>(end - primitives.get());
  return primitives;
}

// Every node's linear bounds, leaves from their primitives and inner nodes as their children's
// union (children come after their parent in `nodes`), where some geometry of `group` moves. The
// nodes' own boxes, built from the primitives halfway through the shutter, become the boxes of
// the whole motion (the linear bounds' two ends), for whatever traces without a time.
std::vector<MotionNode, HugePageAllocator<MotionNode>> motion_nodes_of(const Group& group,
                                                                       std::span<const BBox> prototype_bounds,
                                                                       Bvh& bvh) {
  bool moves = false;
  for (std::uint32_t g = 0; g < group.geometries.size(); ++g) moves = moves || group.motion_step_count(g) > 0;
  if (!moves) return {};
  std::vector<LinearBounds> bounds(bvh.nodes.size());
  tbb::parallel_for(std::size_t{0}, bvh.nodes.size(), [&](std::size_t n) {
    const BvhNode& node = bvh.nodes[n];
    if (!node.is_leaf()) return;
    LinearBounds leaf;
    for (std::uint32_t i = node.index; i < node.index + node.count; ++i) {
      const PrimitiveRef& ref = bvh.refs[i];
      const LinearBounds prim = primitive_linear_bounds(group, ref.geom, ref.prim, prototype_bounds);
      leaf.at_open.extend(prim.at_open);
      leaf.at_close.extend(prim.at_close);
    }
    bounds[n] = leaf;
  });
  for (std::size_t n = bvh.nodes.size(); n-- > 0;) {
    const BvhNode& node = bvh.nodes[n];
    if (node.is_leaf()) continue;
    bounds[n] = bounds[node.index];
    bounds[n].at_open.extend(bounds[node.index + 1].at_open);
    bounds[n].at_close.extend(bounds[node.index + 1].at_close);
  }
  std::vector<MotionNode, HugePageAllocator<MotionNode>> nodes(bvh.nodes.size());
  for (std::size_t n = 0; n < bvh.nodes.size(); ++n) {
    BvhNode& node = bvh.nodes[n];
    node.bounds = bounds[n].at_open;
    node.bounds.extend(bounds[n].at_close);
    nodes[n] = {bounds[n], node.index, node.count, node.axis};
  }
  return nodes;
}

}  // namespace

Bvh build_bvh(const Group& group, std::span<const BBox> prototype_bounds, BvhBuildMode mode) {
  std::uint32_t count = 0;
  auto primitives = build_primitives(group, prototype_bounds, count);
  Bvh bvh = BvhBuilder(std::move(primitives), count, mode == BvhBuildMode::kParallel).build();
  bvh.motion_nodes = motion_nodes_of(group, prototype_bounds, bvh);
  return bvh;
}

}  // namespace rtpro
