#include "bvh_binning.h"

#include "box4.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <array>
#include <limits>

namespace rtpro::bvh_build {

namespace {

// The bins of one range along all three axes: per bin, a box and a primitive count for each axis
// (lanes 0-2 of `counts`; lane 3 is unused).
struct AxisBins {
  std::array<std::array<Box4, 3>, kBinCount> boxes;  // [bin][axis]
  alignas(16) std::array<std::array<std::int32_t, 4>, kBinCount> counts{};

  void join(const AxisBins& other) {
    for (int k = 0; k < kBinCount; ++k) {
      for (int axis = 0; axis < 3; ++axis)
        boxes[k][axis].extend(other.boxes[k][axis].lower, other.boxes[k][axis].upper);
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

// bin_of lane by lane: cvttps2dq truncates as static_cast<int> does (and gives INT_MIN where
// it is out of range, as cvttss2si does), then the same clamp with SSE2's compares.
__m128i bin_of(__m128 values, __m128 lo, __m128 scale) {
  const __m128i b = _mm_cvttps_epi32(_mm_mul_ps(_mm_sub_ps(values, lo), scale));
  const __m128i zero = _mm_setzero_si128(), last = _mm_set1_epi32(kBinCount - 1);
  const __m128i at_least_zero = _mm_andnot_si128(_mm_cmplt_epi32(b, zero), b);
  const __m128i above = _mm_cmpgt_epi32(at_least_zero, last);
  return _mm_or_si128(_mm_and_si128(above, last), _mm_andnot_si128(above, at_least_zero));
}

// The bins of all three axes in one pass over the range: each bin still sees its primitives in
// array order, so this is exactly three separate passes' result. An axis whose centroids do
// not spread gets scale 0 (every primitive in bin 0) and is not used.
AxisBins bin(const BuildPrimitive* primitives, std::uint32_t begin, std::uint32_t end, const BBox& centroids,
             bool parallel) {
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
      const BuildPrimitive& p = primitives[i];
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
  if (!parallel || end - begin < kParallelRange) return fold(begin, end);
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

}  // namespace

// The sweeps run over the three axes at once, one lane each, with the scalar operations in
// their order; the choice among the costs stays scalar, in the order axis by axis, bin by bin.
Split best_sah_split(const BuildPrimitive* primitives, std::uint32_t begin, std::uint32_t end, const RangeBounds& range,
                     bool parallel) {
  const AxisBins bins = bin(primitives, begin, end, range.centroids, parallel);
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

}  // namespace rtpro::bvh_build
