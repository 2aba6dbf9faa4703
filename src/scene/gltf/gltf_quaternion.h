#pragma once
// Unit quaternions as glTF writes rotations (x, y, z, w), in double: the node rotations of the
// loader and the rotations animations interpolate.
#include "rtpro/core/transform.h"

#include <cmath>

namespace rtpro::gltf {

struct Quaternion {
  double x = 0.0, y = 0.0, z = 0.0, w = 1.0;
};

inline double dot(const Quaternion& a, const Quaternion& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

// `q` scaled to unit length; the identity for a zero quaternion (callers refuse those from files).
inline Quaternion normalized(const Quaternion& q) {
  const double norm = std::sqrt(dot(q, q));
  if (!(norm > 0.0)) return {};
  return {q.x / norm, q.y / norm, q.z / norm, q.w / norm};
}

// Spherical interpolation from a (s = 0) to b (s = 1) along the shorter arc, as the glTF
// specification's LINEAR rotation sampler does; nearly equal rotations are interpolated linearly,
// where the sine below would lose its precision. The result is unit length. a and b need not be:
// a key stands for the rotation it normalises to (as it does at its own time), so the turn between
// two keys written slightly off unit length still runs at a steady angular speed.
inline Quaternion slerp(Quaternion a, Quaternion b, double s) {
  a = normalized(a);
  b = normalized(b);
  double cosine = dot(a, b);
  if (cosine < 0.0) {
    cosine = -cosine;
    b = {-b.x, -b.y, -b.z, -b.w};
  }
  double wa = 1.0 - s, wb = s;
  if (cosine < 0.9999) {
    const double angle = std::acos(cosine), sine = std::sin(angle);
    wa = std::sin((1.0 - s) * angle) / sine;
    wb = std::sin(s * angle) / sine;
  }
  return normalized({wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z, wa * a.w + wb * b.w});
}

// The rotation matrix of a unit quaternion.
inline Affine rotation_matrix(const Quaternion& q) {
  const double x = q.x, y = q.y, z = q.z, w = q.w;
  Affine r;
  r.m = {{{float(1 - 2 * (y * y + z * z)), float(2 * (x * y - z * w)), float(2 * (x * z + y * w)), 0.0f},
          {float(2 * (x * y + z * w)), float(1 - 2 * (x * x + z * z)), float(2 * (y * z - x * w)), 0.0f},
          {float(2 * (x * z - y * w)), float(2 * (y * z + x * w)), float(1 - 2 * (x * x + y * y)), 0.0f}}};
  return r;
}

}  // namespace rtpro::gltf
