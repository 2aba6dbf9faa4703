#pragma once
// Reference ray/triangle intersector (Möller–Trumbore evaluated in double precision).
// Barycentrics follow Embree's convention: p = (1−u−v)·p0 + u·p1 + v·p2.
#include "rtpro/core/vec3.h"

namespace rtpro {

struct TriangleHit {
  float t, u, v;
};

// Nearest hit with tnear < t <= tfar. Edges are inclusive (u, v >= 0, u + v <= 1), so a ray
// through a shared edge hits at least one of the two triangles.
inline bool intersect_triangle(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& org, const Vec3& dir,
                               float tnear, float tfar, TriangleHit& hit) {
  const double e1x = double(p1.x) - p0.x, e1y = double(p1.y) - p0.y, e1z = double(p1.z) - p0.z;
  const double e2x = double(p2.x) - p0.x, e2y = double(p2.y) - p0.y, e2z = double(p2.z) - p0.z;
  const double dx = dir.x, dy = dir.y, dz = dir.z;

  const double px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
  const double det = e1x * px + e1y * py + e1z * pz;
  if (det == 0.0) return false;  // ray parallel to the plane, or degenerate triangle
  const double inv_det = 1.0 / det;

  const double sx = double(org.x) - p0.x, sy = double(org.y) - p0.y, sz = double(org.z) - p0.z;
  const double u = (sx * px + sy * py + sz * pz) * inv_det;
  if (u < 0.0 || u > 1.0) return false;

  const double qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
  const double v = (dx * qx + dy * qy + dz * qz) * inv_det;
  if (v < 0.0 || u + v > 1.0) return false;

  const float t = static_cast<float>((e2x * qx + e2y * qy + e2z * qz) * inv_det);
  if (!(t > tnear && t <= tfar)) return false;
  hit = {t, static_cast<float>(u), static_cast<float>(v)};
  return true;
}

}  // namespace rtpro
