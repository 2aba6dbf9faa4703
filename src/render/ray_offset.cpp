#include "rtpro/render/ray_offset.h"

#include <cmath>
#include <limits>

namespace rtpro {

Vec3 offset_ray_origin(const SurfacePoint& surface, const Vec3& direction) {
  const Vec3& n = surface.geometric_normal;
  const float distance = dot(abs(n), Vec3(surface.position_error));
  Vec3 offset = n * distance;
  if (dot(direction, n) < 0.0f) offset = -offset;
  Vec3 origin = surface.position + offset;
  // Round each coordinate away from the surface so the float sum cannot land back on it.
  for (int axis = 0; axis < 3; ++axis) {
    if (offset[axis] > 0.0f) origin[axis] = std::nextafter(origin[axis], std::numeric_limits<float>::infinity());
    else if (offset[axis] < 0.0f) origin[axis] = std::nextafter(origin[axis], -std::numeric_limits<float>::infinity());
  }
  return origin;
}

Ray spawn_ray(const SurfacePoint& surface, const Vec3& direction) {
  Ray ray;
  ray.org = offset_ray_origin(surface, direction);
  ray.dir = direction;
  return ray;
}

Ray spawn_ray_to(const SurfacePoint& surface, const Vec3& target) {
  Ray ray;
  ray.org = offset_ray_origin(surface, target - surface.position);
  ray.dir = target - ray.org;
  // Stop just short of the target so a light placed on a surface is not shadowed by it.
  ray.tfar = 1.0f - 0x1p-16f;
  return ray;
}

}  // namespace rtpro
