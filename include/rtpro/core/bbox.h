#pragma once
#include "rtpro/core/vec3.h"

#include <limits>

namespace rtpro {

struct BBox {
  Vec3 lower{std::numeric_limits<float>::infinity()};
  Vec3 upper{-std::numeric_limits<float>::infinity()};

  bool empty() const { return lower.x > upper.x || lower.y > upper.y || lower.z > upper.z; }
  void extend(const Vec3& p) {
    lower = min(lower, p);
    upper = max(upper, p);
  }
  void extend(const BBox& b) {
    lower = min(lower, b.lower);
    upper = max(upper, b.upper);
  }
  Vec3 center() const { return (lower + upper) * 0.5f; }
  Vec3 extent() const { return upper - lower; }
  float surface_area() const {
    if (empty()) return 0.0f;
    const Vec3 e = extent();
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  int largest_axis() const {
    const Vec3 e = extent();
    return (e.x >= e.y && e.x >= e.z) ? 0 : (e.y >= e.z ? 1 : 2);
  }
};

inline BBox merge(BBox a, const BBox& b) {
  a.extend(b);
  return a;
}

}  // namespace rtpro
