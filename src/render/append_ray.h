#pragma once
// Appending a just-built ray to a batch without a store-forwarding stall.
#include "rtpro/core/ray.h"

#include <vector>

namespace rtpro {

// Appends `ray` field by field. push_back(ray) of a ray a function has just returned or built made
// the compiler copy it with 16-byte loads over the 4- and 8-byte stores that wrote it: a
// store-forwarding stall per ray (about a sixth of the shading loop, and of camera-ray set-up).
inline void append_ray(std::vector<Ray>& rays, const Ray& ray) {
  Ray& r = rays.emplace_back();
  r.org.x = ray.org.x;
  r.org.y = ray.org.y;
  r.org.z = ray.org.z;
  r.tnear = ray.tnear;
  r.dir.x = ray.dir.x;
  r.dir.y = ray.dir.y;
  r.dir.z = ray.dir.z;
  r.tfar = ray.tfar;
}

}  // namespace rtpro
