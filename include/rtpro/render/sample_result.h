#pragma once
// What an integrator returns for one camera sample and the film sums: its radiance and what the
// camera ray itself hit.
#include "rtpro/core/vec3.h"

#include <cstdint>

namespace rtpro {

// The motion AOV's source (aov.h): where the camera ray's hit moves on the film, in pixels per
// frame (+x right, +y down), over the shutter's second half (forward_x, forward_y: towards the
// next frame) and its first half (back_x, back_y: from the previous frame). 0 when nothing moves.
struct FilmMotion {
  float forward_x = 0.0f, forward_y = 0.0f;
  float back_x = 0.0f, back_y = 0.0f;
};

// What the camera ray itself hit: the sources of the AOV passes.
struct PrimaryHit {
  bool hit = false;
  Color albedo;
  Vec3 normal;         // shading normal, world space, unit
  float depth = 0.0f;  // distance from the camera
  std::uint32_t object_id = 0;
  FilmMotion motion = {};  // worked out only when the motion AOV is kept
};

// One camera sample's result: its radiance and the sources of its AOV passes.
struct SampleResult {
  Color radiance;
  PrimaryHit primary;
};

}  // namespace rtpro
