#pragma once
#include "rtpro/core/vec3.h"

#include <cmath>
#include <limits>

namespace rtpro {

// A ray segment: points org + t·dir for t in the open-closed interval (tnear, tfar].
// dir need not be unit length; t is always measured in units of dir.
struct Ray {
  Vec3 org;
  float tnear = 0.0f;
  Vec3 dir;
  float tfar = std::numeric_limits<float>::infinity();

  Vec3 at(float t) const { return org + dir * t; }
};

// Coordinates Embree handles safely: finite and far below the ~1.8e18 at which its ray validity
// assertion fires (and beyond which its commit silently drops primitives), far beyond any scene.
inline constexpr float kMaxTraceableMagnitude = 1e16f;
inline bool within_traceable_range(const Vec3& v) {
  return is_finite(v) && std::fabs(v.x) < kMaxTraceableMagnitude && std::fabs(v.y) < kMaxTraceableMagnitude &&
         std::fabs(v.z) < kMaxTraceableMagnitude;
}

// What a backend accepts: finite origin and direction, a non-zero direction, 0 <= tnear <= tfar, and
// magnitudes far below the range where Embree's own validity assertion aborts the process.
// Inline: every ray of every backend passes through it.
inline bool is_traceable(const Ray& ray) {
  if (!within_traceable_range(ray.org) || !within_traceable_range(ray.dir)) return false;
  if (ray.dir.x == 0.0f && ray.dir.y == 0.0f && ray.dir.z == 0.0f) return false;
  if (!std::isfinite(ray.tnear) || std::isnan(ray.tfar)) return false;
  return ray.tnear >= 0.0f && ray.tnear <= ray.tfar;
}

}  // namespace rtpro
