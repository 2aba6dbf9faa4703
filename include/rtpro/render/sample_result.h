#pragma once
// What an integrator returns for one camera sample and the film sums: its radiance and what the
// camera ray itself hit.
#include "rtpro/core/vec3.h"

#include <cstdint>

namespace rtpro {

// What the camera ray itself hit: the sources of the AOV passes.
struct PrimaryHit {
  bool hit = false;
  Color albedo;
  Vec3 normal;         // shading normal, world space, unit
  float depth = 0.0f;  // distance from the camera
  std::uint32_t object_id = 0;
};

// One camera sample's result: its radiance and the sources of its AOV passes.
struct SampleResult {
  Color radiance;
  PrimaryHit primary;
};

}  // namespace rtpro
