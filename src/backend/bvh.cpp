#include "bvh.h"

#include <algorithm>
#include <array>

namespace rtpro {

namespace {

constexpr int kBinCount = 16;
constexpr int kMaxLeafSize = 8;
constexpr float kTraversalCost = 1.0f;  // relative to one primitive test
// Below this depth limit the builder may follow SAH freely; past it, it splits at the median so
// that the tree depth (and the traversal stack) stays bounded on adversarial input.
constexpr int kSahDepthLimit = kBvhMaxDepth - 32;

struct BuildPrimitive {
  BBox bounds;
  Vec3 centroid;
  PrimitiveRef ref;
};

struct Bin {
  BBox bounds;
  int count = 0;
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  float cost = 0.0f;
};

class BvhBuilder {
 public:
  explicit BvhBuilder(std::vector<BuildPrimitive> primitives) : prims_(std::move(primitives)) {}

  Bvh build() {
    Bvh bvh;
    if (prims_.empty()) return bvh;
    bvh.nodes.reserve(prims_.size());
    struct Task {
      std::uint32_t node, begin, end;
      int depth;
    };
    std::vector<Task> stack;
    bvh.nodes.push_back({});
    stack.push_back({0, 0, static_cast<std::uint32_t>(prims_.size()), 0});
    while (!stack.empty()) {
      const Task task = stack.back();
      stack.pop_back();
      BBox bounds, centroids;
      for (std::uint32_t i = task.begin; i < task.end; ++i) {
        bounds.extend(prims_[i].bounds);
        centroids.extend(prims_[i].centroid);
      }
      const std::uint32_t count = task.end - task.begin;
      int axis = 0;
      const std::uint32_t mid = choose_partition(task.begin, task.end, centroids, task.depth, axis);
      if (mid == task.begin) {
        bvh.nodes[task.node] = {bounds, task.begin, static_cast<std::uint16_t>(count), 0};
        continue;
      }
      // Siblings are allocated as a pair, so one index finds both children.
      const std::uint32_t left = static_cast<std::uint32_t>(bvh.nodes.size());
      const std::uint32_t right = left + 1;
      bvh.nodes.push_back({});
      bvh.nodes.push_back({});
      bvh.nodes[task.node] = {bounds, left, 0, static_cast<std::uint16_t>(axis)};
      stack.push_back({right, mid, task.end, task.depth + 1});
      stack.push_back({left, task.begin, mid, task.depth + 1});
    }
    bvh.refs.reserve(prims_.size());
    for (const BuildPrimitive& p : prims_) bvh.refs.push_back(p.ref);
    return bvh;
  }

 private:
  // Returns the split position in [begin, end), or begin to make a leaf; sets `axis` to the
  // axis the primitives were separated along.
  std::uint32_t choose_partition(std::uint32_t begin, std::uint32_t end, const BBox& centroids, int depth,
                                 int& axis) {
    const std::uint32_t count = end - begin;
    if (count <= 2) return begin;
    axis = centroids.largest_axis();
    const float extent = centroids.extent()[axis];
    if (!(extent > 0.0f)) {
      // All centroids coincide: SAH cannot separate them, so split by position in the array.
      return count <= kMaxLeafSize ? begin : begin + count / 2;
    }
    if (depth >= kSahDepthLimit) return median_split(begin, end, axis);

    const Split split = best_sah_split(begin, end, centroids);
    const float leaf_cost = static_cast<float>(count);
    if (split.axis < 0) return count <= kMaxLeafSize ? begin : median_split(begin, end, axis);
    if (split.cost >= leaf_cost && count <= kMaxLeafSize) return begin;

    axis = split.axis;
    const float lo = centroids.lower[split.axis];
    const float scale = kBinCount / centroids.extent()[split.axis];
    auto* middle = std::partition(prims_.data() + begin, prims_.data() + end, [&](const BuildPrimitive& p) {
      return bin_of(p.centroid[split.axis], lo, scale) <= split.bin;
    });
    const auto mid = static_cast<std::uint32_t>(middle - prims_.data());
    if (mid == begin || mid == end) return median_split(begin, end, axis);
    return mid;
  }

  static int bin_of(float value, float lo, float scale) {
    const int b = static_cast<int>((value - lo) * scale);
    return std::clamp(b, 0, kBinCount - 1);
  }

  Split best_sah_split(std::uint32_t begin, std::uint32_t end, const BBox& centroids) const {
    Split best;
    float best_cost = 0.0f;
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = centroids.extent()[axis];
      if (!(extent > 0.0f)) continue;
      const float lo = centroids.lower[axis];
      const float scale = kBinCount / extent;
      std::array<Bin, kBinCount> bins{};
      for (std::uint32_t i = begin; i < end; ++i) {
        Bin& bin = bins[bin_of(prims_[i].centroid[axis], lo, scale)];
        bin.bounds.extend(prims_[i].bounds);
        ++bin.count;
      }
      // Sweep from the right to get the area × count of every right side, then from the left.
      std::array<float, kBinCount> right_cost{};
      BBox right;
      int right_count = 0;
      for (int b = kBinCount - 1; b > 0; --b) {
        right.extend(bins[b].bounds);
        right_count += bins[b].count;
        right_cost[b] = right.surface_area() * right_count;
      }
      BBox left;
      int left_count = 0;
      for (int b = 0; b < kBinCount - 1; ++b) {
        left.extend(bins[b].bounds);
        left_count += bins[b].count;
        if (left_count == 0 || left_count == static_cast<int>(end - begin)) continue;
        const float cost = left.surface_area() * left_count + right_cost[b + 1];
        if (best.axis < 0 || cost < best_cost) {
          best = {axis, b, 0.0f};
          best_cost = cost;
        }
      }
    }
    if (best.axis >= 0) {
      BBox all;
      for (std::uint32_t i = begin; i < end; ++i) all.extend(prims_[i].bounds);
      const float area = all.surface_area();
      best.cost = area > 0.0f ? kTraversalCost + best_cost / area : kTraversalCost;
    }
    return best;
  }

  std::uint32_t median_split(std::uint32_t begin, std::uint32_t end, int axis) {
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(prims_.begin() + begin, prims_.begin() + mid, prims_.begin() + end,
                     [axis](const BuildPrimitive& a, const BuildPrimitive& b) {
                       const float ca = a.centroid[axis], cb = b.centroid[axis];
                       if (ca != cb) return ca < cb;
                       return a.ref.geom != b.ref.geom ? a.ref.geom < b.ref.geom : a.ref.prim < b.ref.prim;
                     });
    return mid;
  }

  std::vector<BuildPrimitive> prims_;
};

}  // namespace

Bvh build_bvh(const Group& group, std::span<const BBox> prototype_bounds) {
  std::size_t total = 0;
  for (std::uint32_t g = 0; g < group.geometries.size(); ++g) total += group.primitive_count(g);
  std::vector<BuildPrimitive> primitives;
  primitives.reserve(total);
  for (std::uint32_t g = 0; g < group.geometries.size(); ++g) {
    const std::uint32_t count = group.primitive_count(g);
    for (std::uint32_t p = 0; p < count; ++p) {
      const BBox b = group.primitive_bounds(g, p, prototype_bounds);
      if (b.empty()) continue;  // e.g. an instance of an empty prototype
      primitives.push_back({b, b.center(), {g, p}});
    }
  }
  return BvhBuilder(std::move(primitives)).build();
}

}  // namespace rtpro
