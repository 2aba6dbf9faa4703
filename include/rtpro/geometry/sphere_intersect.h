#pragma once
// The analytic ray/sphere intersector. Both backends call this one function (the Embree backend
// from its user-geometry callback), so top-level sphere hits are bit-identical between them.
//
// The quadratic is solved in double precision with the numerically stable discriminant of
// Ray Tracing Gems ch. 7 (r² − |f − (f·d/d·d)·d|²) and the cancellation-free root pair
// q/a, c/q, then each root is rounded to float and tested against the float interval. That keeps
// far-away small spheres, origins inside the sphere, tangent rays and non-unit directions right.
#include "rtpro/core/vec3.h"

#include <cmath>

namespace rtpro {

// Nearest root t of |org + t·dir − center| = radius with tnear < t <= tfar, or false.
// The closed upper end lets callers apply their own tie rule on exactly equal distances.
inline bool intersect_sphere(const Vec3& center, float radius, const Vec3& org, const Vec3& dir, float tnear,
                             float tfar, float& t_hit) {
  const double fx = double(org.x) - double(center.x);
  const double fy = double(org.y) - double(center.y);
  const double fz = double(org.z) - double(center.z);
  const double dx = dir.x, dy = dir.y, dz = dir.z;

  const double a = dx * dx + dy * dy + dz * dz;
  if (!(a > 0.0)) return false;
  const double b = fx * dx + fy * dy + fz * dz;  // half of the usual b
  const double r = radius;
  const double c = (fx * fx + fy * fy + fz * fz) - r * r;
  // Origin outside (c > 0) and moving away from the centre (b > 0): both roots are negative (or
  // flush to −0), so neither lies in (tnear, tfar] with tnear >= 0. Leaving early changes no answer
  // and skips the divisions and the square root for the most common miss: a shadow ray leaving
  // the surface it starts on.
  if (c > 0.0 && b > 0.0 && tnear >= 0.0f) return false;

  // Distance² from the centre to the line, computed without squaring large near-equal numbers.
  const double s = b / a;
  const double lx = fx - s * dx, ly = fy - s * dy, lz = fz - s * dz;
  const double disc = a * (r * r - (lx * lx + ly * ly + lz * lz));
  if (disc < 0.0) return false;

  const double root = std::sqrt(disc);
  const double q = -(b + std::copysign(root, b));
  double t0, t1;
  if (q == 0.0) {
    t0 = t1 = 0.0;  // origin on the sphere, ray tangent to it
  } else {
    t0 = q / a;
    t1 = c / q;
    if (t0 > t1) {
      const double tmp = t0;
      t0 = t1;
      t1 = tmp;
    }
  }

  const float near_root = static_cast<float>(t0);
  if (near_root > tnear && near_root <= tfar) {
    t_hit = near_root;
    return true;
  }
  const float far_root = static_cast<float>(t1);
  if (far_root > tnear && far_root <= tfar) {
    t_hit = far_root;
    return true;
  }
  return false;
}

}  // namespace rtpro
