#pragma once
#include "rtpro/core/vec3.h"

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
bool within_traceable_range(const Vec3& v);

// What a backend accepts: finite origin and direction, a non-zero direction, 0 <= tnear <= tfar, and
// magnitudes far below the range where Embree's own validity assertion aborts the process.
bool is_traceable(const Ray& ray);

}  // namespace rtpro
