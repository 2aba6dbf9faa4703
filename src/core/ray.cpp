#include "rtpro/core/ray.h"

#include <cmath>

namespace rtpro {

bool within_traceable_range(const Vec3& v) {
  return is_finite(v) && std::fabs(v.x) < kMaxTraceableMagnitude && std::fabs(v.y) < kMaxTraceableMagnitude &&
         std::fabs(v.z) < kMaxTraceableMagnitude;
}

bool is_traceable(const Ray& ray) {
  if (!within_traceable_range(ray.org) || !within_traceable_range(ray.dir)) return false;
  if (ray.dir.x == 0.0f && ray.dir.y == 0.0f && ray.dir.z == 0.0f) return false;
  if (!std::isfinite(ray.tnear) || std::isnan(ray.tfar)) return false;
  return ray.tnear >= 0.0f && ray.tnear <= ray.tfar;
}

}  // namespace rtpro
