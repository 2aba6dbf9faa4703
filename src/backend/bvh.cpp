#include "bvh.h"

#include "box4.h"
#include "rtpro/core/huge_page_buffer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>

namespace rtpro {

namespace {

constexpr int kBinCount = 16;
constexpr int kMaxLeafSize = 8;
constexpr float kTraversalCost = 1.0f;  // relative to one primitive test
// Below this depth limit the builder may follow SAH freely; past it, it splits at the median so
// that the tree depth (and the traversal stack) stays bounded on adversarial input.
constexpr int kSahDepthLimit = kBvhMaxDepth - 32;
// Subtrees of at most this many primitives are built by one task; larger ones split their two
// children across tasks. Ranges of at least kParallelRange primitives are bounded and binned in
// parallel, in chunks of kChunk.
constexpr std::uint32_t kParallelSubtree = 4096;
constexpr std::uint32_t kParallelRange = 32768;
constexpr std::size_t kChunk = 8192;

// Trivially constructible, so that an array of them is filled by parallel tasks without first
// being initialised by one thread (those first writes were a seventh of the build).
// 32 bytes, the reference in the bounds' fourth lanes: every level of the build streams the whole
// array two or three times, so its size is the build's memory traffic. The centroid is computed
// where it is needed, with BBox::center's operations.
struct alignas(16) BuildPrimitive {
  float lower[3];
  std::uint32_t geom;
  float upper[3];
  std::uint32_t prim;

  BBox bounds() const { return {{lower[0], lower[1], lower[2]}, {upper[0], upper[1], upper[2]}}; }
  float centroid(int axis) const { return (lower[axis] + upper[axis]) * 0.5f; }
  PrimitiveRef ref() const { return {geom, prim}; }
};
static_assert(sizeof(BuildPrimitive) == 32);
static_assert(std::is_trivially_default_constructible_v<BuildPrimitive>);

// The bins of one range along all three axes: per bin, a box and a primitive count for each axis
// (lanes 0-2 of `counts`; lane 3 is unused).
struct AxisBins {
  std::array<std::array<Box4, 3>, kBinCount> boxes;  // [bin][axis]
  alignas(16) std::array<std::array<std::int32_t, 4>, kBinCount> counts{};

  void join(const AxisBins& other) {
    for (int k = 0; k < kBinCount; ++k) {
      for (int axis = 0; axis < 3; ++axis) boxes[k][axis].extend(other.boxes[k][axis].lower, other.boxes[k][axis].upper);
      for (int axis = 0; axis < 3; ++axis) counts[k][axis] += other.counts[k][axis];
    }
  }
};

// Three boxes, one per lane: lower[c] and upper[c] hold coordinate c of each box (lane 3 unused).
struct Boxes3 {
  __m128 lower[3], upper[3];

  Boxes3() {
    for (int c = 0; c < 3; ++c) {
      lower[c] = _mm_set1_ps(std::numeric_limits<float>::infinity());
      upper[c] = _mm_set1_ps(-std::numeric_limits<float>::infinity());
    }
  }
  // Box4::extend (and so BBox::extend) lane by lane, for the three boxes of one bin.
  void extend(const std::array<Box4, 3>& boxes) {
    __m128 lo[4] = {boxes[0].lower, boxes[1].lower, boxes[2].lower, _mm_setzero_ps()};
    __m128 hi[4] = {boxes[0].upper, boxes[1].upper, boxes[2].upper, _mm_setzero_ps()};
    _MM_TRANSPOSE4_PS(lo[0], lo[1], lo[2], lo[3]);
    _MM_TRANSPOSE4_PS(hi[0], hi[1], hi[2], hi[3]);
    for (int c = 0; c < 3; ++c) {
      lower[c] = _mm_min_ps(lo[c], lower[c]);
      upper[c] = _mm_max_ps(hi[c], upper[c]);
    }
  }
  // BBox::surface_area of each box, with its operations in its order: 0 for an empty box, else
  // 2 * ((ex * ey + ey * ez) + ez * ex).
  __m128 surface_areas() const {
    const __m128 ex = _mm_sub_ps(upper[0], lower[0]);
    const __m128 ey = _mm_sub_ps(upper[1], lower[1]);
    const __m128 ez = _mm_sub_ps(upper[2], lower[2]);
    const __m128 sum = _mm_add_ps(_mm_add_ps(_mm_mul_ps(ex, ey), _mm_mul_ps(ey, ez)), _mm_mul_ps(ez, ex));
    const __m128 area = _mm_mul_ps(_mm_set1_ps(2.0f), sum);
    const __m128 empty = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(lower[0], upper[0]), _mm_cmpgt_ps(lower[1], upper[1])),
                                   _mm_cmpgt_ps(lower[2], upper[2]));
    return _mm_andnot_ps(empty, area);
  }
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  float cost = 0.0f;
};

struct RangeBounds {
  BBox bounds;     // of the primitives
  BBox centroids;  // of their centroids
};

// What one node does with its range: a leaf when mid == begin, else children [begin, mid) and
// [mid, end) split along `axis`.
struct Decision {
  BBox bounds;
  std::uint32_t mid;
  int axis;
};

// A primitive's bounds as two lanes-of-four. The fourth lanes hold the reference's bits, which
// min and max carry along and no result reads.
__m128 lower4(const BuildPrimitive& p) { return _mm_load_ps(p.lower); }
__m128 upper4(const BuildPrimitive& p) { return _mm_load_ps(p.upper); }
// The centroid, lane by lane as BBox::center computes it, the fourth lane 0: the reference's bits
// could be denormals, which arithmetic on some processors takes slow paths for.
__m128 centroid4(__m128 lower, __m128 upper) {
  const __m128 xyz = _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0));
  return _mm_mul_ps(_mm_add_ps(_mm_and_ps(lower, xyz), _mm_and_ps(upper, xyz)), _mm_set1_ps(0.5f));
}

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
  static void place(const Part& part, std::uint32_t slot, std::uint32_t& next, Nodes& nodes, std::vector<Copy>& copies) {
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
        [&](const tbb::blocked_range<std::uint32_t>& r, Value value) { return fold(value, r.begin(), r.end()); },
        join, tbb::simple_partitioner());
  }

  RangeBounds bounds_of(std::uint32_t begin, std::uint32_t end) const {
    return reduce_range<RangeBounds>(
        begin, end,
        [this](RangeBounds r, std::uint32_t b, std::uint32_t e) {
          Box4 bounds(r.bounds), centroids(r.centroids);
          for (std::uint32_t i = b; i < e; ++i) {
            const BuildPrimitive& p = prims_[i];
            const __m128 lower = lower4(p), upper = upper4(p);
            bounds.extend(lower, upper);
            const __m128 c = centroid4(lower, upper);
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

    const Split split = best_sah_split(begin, end, range);
    const float leaf_cost = static_cast<float>(count);
    if (split.axis < 0) return count <= kMaxLeafSize ? begin : median_split(begin, end, axis);
    if (split.cost >= leaf_cost && count <= kMaxLeafSize) return begin;

    axis = split.axis;
    const float lo = centroids.lower[split.axis];
    const float scale = kBinCount / centroids.extent()[split.axis];
    // std::partition, not a parallel one: its exact order of the two sides is part of the tree.
    auto* middle = std::partition(prims_.get() + begin, prims_.get() + end, [&](const BuildPrimitive& p) {
      return bin_of(p.centroid(split.axis), lo, scale) <= split.bin;
    });
    const auto mid = static_cast<std::uint32_t>(middle - prims_.get());
    if (mid == begin || mid == end) return median_split(begin, end, axis);
    return mid;
  }

  static int bin_of(float value, float lo, float scale) {
    const int b = static_cast<int>((value - lo) * scale);
    return std::clamp(b, 0, kBinCount - 1);
  }

  // bin_of lane by lane: cvttps2dq truncates as static_cast<int> does (and gives INT_MIN where
  // it is out of range, as cvttss2si does), then the same clamp with SSE2's compares.
  static __m128i bin_of(__m128 values, __m128 lo, __m128 scale) {
    const __m128i b = _mm_cvttps_epi32(_mm_mul_ps(_mm_sub_ps(values, lo), scale));
    const __m128i zero = _mm_setzero_si128(), last = _mm_set1_epi32(kBinCount - 1);
    const __m128i at_least_zero = _mm_andnot_si128(_mm_cmplt_epi32(b, zero), b);
    const __m128i above = _mm_cmpgt_epi32(at_least_zero, last);
    return _mm_or_si128(_mm_and_si128(above, last), _mm_andnot_si128(above, at_least_zero));
  }

  // The bins of all three axes in one pass over the range: each bin still sees its primitives in
  // array order, so this is exactly three separate passes' result. An axis whose centroids do
  // not spread gets scale 0 (every primitive in bin 0) and is not used.
  AxisBins bin(std::uint32_t begin, std::uint32_t end, const BBox& centroids) const {
    alignas(16) float lo[4] = {centroids.lower.x, centroids.lower.y, centroids.lower.z, 0.0f};
    alignas(16) float scale[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = centroids.extent()[axis];
      if (extent > 0.0f) scale[axis] = kBinCount / extent;
    }
    const __m128 lo4 = _mm_load_ps(lo), scale4 = _mm_load_ps(scale);
    // Fresh bins for [b, e): the per-node cost matters as much as the per-primitive one, since
    // most of the ~450,000 nodes of a million-triangle tree cover a few dozen primitives.
    auto fold = [&](std::uint32_t b, std::uint32_t e) {
      AxisBins bins;
      alignas(16) std::int32_t k[4];
      for (std::uint32_t i = b; i < e; ++i) {
        const BuildPrimitive& p = prims_[i];
        const __m128 lower = lower4(p), upper = upper4(p);
        // bin_of for the three axes at once (lane 3 is never read).
        _mm_store_si128(reinterpret_cast<__m128i*>(k), bin_of(centroid4(lower, upper), lo4, scale4));
        for (int axis = 0; axis < 3; ++axis) {
          bins.boxes[k[axis]][axis].extend(lower, upper);
          ++bins.counts[k[axis]][axis];
        }
      }
      return bins;
    };
    if (!parallel_ || end - begin < kParallelRange) return fold(begin, end);
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<std::uint32_t>(begin, end, kChunk), AxisBins{},
        [&](const tbb::blocked_range<std::uint32_t>& r, AxisBins so_far) {
          so_far.join(fold(r.begin(), r.end()));
          return so_far;
        },
        [](AxisBins a, const AxisBins& b) {
          a.join(b);
          return a;
        },
        tbb::simple_partitioner());
  }

  // The sweeps run over the three axes at once, one lane each, with the scalar operations in
  // their order; the choice among the costs stays scalar, in the order axis by axis, bin by bin.
  Split best_sah_split(std::uint32_t begin, std::uint32_t end, const RangeBounds& range) const {
    const AxisBins bins = bin(begin, end, range.centroids);
    // From the right, the area x count of every right side; then from the left, every split's cost.
    alignas(16) float right_cost[kBinCount][4];
    Boxes3 right;
    __m128i right_count = _mm_setzero_si128();
    for (int b = kBinCount - 1; b > 0; --b) {
      right.extend(bins.boxes[b]);
      right_count = _mm_add_epi32(right_count, _mm_load_si128(reinterpret_cast<const __m128i*>(bins.counts[b].data())));
      _mm_store_ps(right_cost[b], _mm_mul_ps(right.surface_areas(), _mm_cvtepi32_ps(right_count)));
    }
    alignas(16) float cost[kBinCount][4];
    alignas(16) std::int32_t left_count[kBinCount][4];
    Boxes3 left;
    __m128i count = _mm_setzero_si128();
    for (int b = 0; b < kBinCount - 1; ++b) {
      left.extend(bins.boxes[b]);
      count = _mm_add_epi32(count, _mm_load_si128(reinterpret_cast<const __m128i*>(bins.counts[b].data())));
      _mm_store_si128(reinterpret_cast<__m128i*>(left_count[b]), count);
      const __m128 left_cost = _mm_mul_ps(left.surface_areas(), _mm_cvtepi32_ps(count));
      _mm_store_ps(cost[b], _mm_add_ps(left_cost, _mm_load_ps(right_cost[b + 1])));
    }

    Split best;
    float best_cost = 0.0f;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(range.centroids.extent()[axis] > 0.0f)) continue;
      for (int b = 0; b < kBinCount - 1; ++b) {
        if (left_count[b][axis] == 0 || left_count[b][axis] == static_cast<std::int32_t>(end - begin)) continue;
        if (best.axis < 0 || cost[b][axis] < best_cost) {
          best = {axis, b, 0.0f};
          best_cost = cost[b][axis];
        }
      }
    }
    if (best.axis >= 0) {
      const float area = range.bounds.surface_area();
      best.cost = area > 0.0f ? kTraversalCost + best_cost / area : kTraversalCost;
    }
    return best;
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

// Every primitive's bounds, computed in parallel into its place in geometry order; primitives
// with empty bounds (an instance of an empty prototype) are then dropped, keeping the order.
HugePageBuffer<BuildPrimitive> build_primitives(const Group& group, std::span<const BBox> prototype_bounds,
                                                   std::uint32_t& count) {
  std::vector<std::size_t> first(group.geometries.size() + 1, 0);
  for (std::uint32_t g = 0; g < group.geometries.size(); ++g) first[g + 1] = first[g] + group.primitive_count(g);
  HugePageBuffer<BuildPrimitive> primitives(first.back());
  tbb::parallel_for(std::uint32_t{0}, static_cast<std::uint32_t>(group.geometries.size()), [&](std::uint32_t g) {
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, group.primitive_count(g), kChunk),
                      [&](const tbb::blocked_range<std::uint32_t>& r) {
                        for (std::uint32_t p = r.begin(); p < r.end(); ++p) {
                          const BBox b = group.primitive_bounds(g, p, prototype_bounds);
                          primitives[first[g] + p] = {{b.lower.x, b.lower.y, b.lower.z}, g,
                                                      {b.upper.x, b.upper.y, b.upper.z}, p};
                        }
                      });
  });
  const auto* end = std::remove_if(primitives.get(), primitives.get() + first.back(),
                                   [](const BuildPrimitive& p) { return p.bounds().empty(); });
  count = static_cast<std::uint32_t>(end - primitives.get());
  return primitives;
}

}  // namespace

Bvh build_bvh(const Group& group, std::span<const BBox> prototype_bounds, BvhBuildMode mode) {
  std::uint32_t count = 0;
  auto primitives = build_primitives(group, prototype_bounds, count);
  return BvhBuilder(std::move(primitives), count, mode == BvhBuildMode::kParallel).build();
}

}  // namespace rtpro
