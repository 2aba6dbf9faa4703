#pragma once
// Where a ray meets one primitive in the native traversal, as each kind's native_hit reports it
// (sphere_backend.h and its neighbours); a sphere has no (u, v).
namespace rtpro {

struct ShapeHit {
  float t, u, v;
};

}  // namespace rtpro
