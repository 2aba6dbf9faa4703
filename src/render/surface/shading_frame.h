#pragma once
// The local frame every BSDF works in: the shading normal is +z, so cos θ is a vector's z and the
// BSDFs never see world space.
#include "rtpro/core/vec3.h"

#include <cmath>

namespace rtpro {

struct ShadingFrame {
  Vec3 s, t, n;

  // Duff et al. 2017, "Building an Orthonormal Basis, Revisited": no branch on the normal, so no
  // seam where the tangents jump, and exact for n = ±z. `n` must be unit; s × t = n.
  static ShadingFrame from_normal(const Vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return {Vec3{1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x}, Vec3{b, sign + n.y * n.y * a, -n.y}, n};
  }

  Vec3 to_local(const Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  Vec3 to_world(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace rtpro
