#include "rtpro/core/ray.h"

#include <cmath>

namespace rtpro {

namespace {
// Far below the ~1.8e18 at which Embree's ray.valid() assertion fires, and far beyond any scene.
constexpr float kMaxMagnitude = 1e16f;

bool in_range(const Vec3& v) {
  return is_finite(v) && std::fabs(v.x) < kMaxMagnitude && std::fabs(v.y) < kMaxMagnitude &&
         std::fabs(v.z) < kMaxMagnitude;
}
}  // namespace

bool is_traceable(const Ray& ray) {
  if (!in_range(ray.org) || !in_range(ray.dir)) return false;
  if (ray.dir.x == 0.0f && ray.dir.y == 0.0f && ray.dir.z == 0.0f) return false;
  if (!std::isfinite(ray.tnear) || std::isnan(ray.tfar)) return false;
  return ray.tnear >= 0.0f && ray.tnear <= ray.tfar;
}

}  // namespace rtpro
