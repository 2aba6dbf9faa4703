#pragma once
// Appending a just-built ray to a batch without a store-forwarding stall.
#include "rtpro/core/ray.h"

#include <vector>

namespace rtpro {

// Copies `ray` into `out` field by field. A whole-record copy of a ray a function has just
// returned or built made the compiler copy it with 16-byte loads over the 4- and 8-byte stores
// that wrote it: a store-forwarding stall per ray (about a sixth of the shading loop, and of
// camera-ray set-up).
[[gnu::always_inline]] inline void copy_ray(const Ray& ray, Ray& out) {
  out.org.x = ray.org.x;
  out.org.y = ray.org.y;
  out.org.z = ray.org.z;
  out.tnear = ray.tnear;
  out.dir.x = ray.dir.x;
  out.dir.y = ray.dir.y;
  out.dir.z = ray.dir.z;
  out.tfar = ray.tfar;
}

// Appends `ray` field by field (copy_ray); always inline, or the copy is made of the record in
// memory after all, merged into wide loads.
[[gnu::always_inline]] inline void append_ray(std::vector<Ray>& rays, const Ray& ray) {
  copy_ray(ray, rays.emplace_back());
}

}  // namespace rtpro
