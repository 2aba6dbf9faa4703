#pragma once
// A bounding box in two SSE registers, for the BVH builder's loops over every primitive.
#include "rtpro/core/bbox.h"

#include <immintrin.h>

#include <limits>

namespace rtpro {

// BBox::extend four lanes at a time (x, y, z and an ignored fourth) for the two loops that run
// over every primitive at every level. _mm_min_ps(x, acc) is (x < acc ? x : acc) and
// _mm_max_ps(x, acc) is (x > acc ? x : acc): exactly what std::min(acc, x) and std::max(acc, x)
// give, ties and NaN included, so the boxes are bit for bit the scalar ones.
struct Box4 {
  __m128 lower = _mm_set1_ps(std::numeric_limits<float>::infinity());
  __m128 upper = _mm_set1_ps(-std::numeric_limits<float>::infinity());

  Box4() = default;
  explicit Box4(const BBox& b)
      : lower(_mm_setr_ps(b.lower.x, b.lower.y, b.lower.z, 0.0f)),
        upper(_mm_setr_ps(b.upper.x, b.upper.y, b.upper.z, 0.0f)) {}
  void extend(__m128 lo, __m128 hi) {
    lower = _mm_min_ps(lo, lower);
    upper = _mm_max_ps(hi, upper);
  }
  BBox box() const {
    alignas(16) float lo[4], hi[4];
    _mm_store_ps(lo, lower);
    _mm_store_ps(hi, upper);
    return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
  }
};

}  // namespace rtpro
