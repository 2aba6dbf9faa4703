#pragma once
// The native BVH builder's binned SAH: the primitives as the builder sorts them, and the search
// for the cheapest split of a range over 16 bins along each axis (bvh.cpp builds the tree).
#include "bvh.h"

#include <immintrin.h>

#include <algorithm>
#include <cstdint>
#include <type_traits>

namespace rtpro::bvh_build {

inline constexpr int kBinCount = 16;
inline constexpr float kTraversalCost = 1.0f;  // relative to one primitive test
// Ranges of at least kParallelRange primitives are bounded and binned in parallel, in chunks of
// kChunk.
inline constexpr std::uint32_t kParallelRange = 32768;
inline constexpr std::size_t kChunk = 8192;

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

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  float cost = 0.0f;
};

struct RangeBounds {
  BBox bounds;     // of the primitives
  BBox centroids;  // of their centroids
};

// A primitive's bounds as two lanes-of-four. The fourth lanes hold the reference's bits, which
// min and max carry along and no result reads.
inline __m128 lower4(const BuildPrimitive& p) { return _mm_load_ps(p.lower); }
inline __m128 upper4(const BuildPrimitive& p) { return _mm_load_ps(p.upper); }
// The centroid, lane by lane as BBox::center computes it, the fourth lane 0: the reference's bits
// could be denormals, which arithmetic on some processors takes slow paths for.
inline __m128 centroid4(__m128 lower, __m128 upper) {
  const __m128 xyz = _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0));
  return _mm_mul_ps(_mm_add_ps(_mm_and_ps(lower, xyz), _mm_and_ps(upper, xyz)), _mm_set1_ps(0.5f));
}

inline int bin_of(float value, float lo, float scale) {
  const int b = static_cast<int>((value - lo) * scale);
  return std::clamp(b, 0, kBinCount - 1);
}

// The cheapest split of primitives [begin, end) by the surface area heuristic, or axis -1 when no
// bin boundary separates them; binned in parallel chunks when `parallel` and the range is large.
Split best_sah_split(const BuildPrimitive* primitives, std::uint32_t begin, std::uint32_t end, const RangeBounds& range,
                     bool parallel);

}  // namespace rtpro::bvh_build
