#pragma once
// The one place secondary rays are spawned. The origin is pushed off the surface along the
// geometric normal by the point's error bound and rounded away from it (pbrt's approach), so a
// spawned ray never re-hits the surface it leaves.
#include "rtpro/core/ray.h"
#include "rtpro/render/surface.h"

namespace rtpro {

Vec3 offset_ray_origin(const SurfacePoint& surface, const Vec3& direction);

// A ray leaving the surface in `direction`.
Ray spawn_ray(const SurfacePoint& surface, const Vec3& direction);

// A ray from the surface to `target`; it spans t in (0, 1) so `target` itself is excluded.
Ray spawn_ray_to(const SurfacePoint& surface, const Vec3& target);

}  // namespace rtpro
