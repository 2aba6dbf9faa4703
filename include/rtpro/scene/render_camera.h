#pragma once
// The camera as the renderer uses it: the scene file's camera (a pinhole, or a thin lens with an
// aperture) with its frame worked out once. Right-handed world, +y up by convention: the image's +x runs along cross(forward, up);
// pixel coordinates are continuous, (0,0) at the top-left corner.
#include "rtpro/core/vec3.h"
#include "rtpro/scene/motion.h"

namespace rtpro {

struct RenderCamera {
  // As the scene file gave them (for reports).
  Vec3 position, look_at, up;
  float fov_degrees = 45.0f;
  int width = 0, height = 0;

  // The frame rays are generated in: unit forward, right and up vectors, and the half extent of
  // the image plane at distance 1.
  Vec3 forward, right, true_up;
  float half_width = 0.0f, half_height = 0.0f;
  float inv_width = 0.0f, inv_height = 0.0f;

  // Thin lens: radius in scene units (0: pinhole) and the focus distance along `forward`.
  float lens_radius = 0.0f;
  float focus_distance = 1.0f;

  // The exposure (scene/motion.h); while open, each camera sample gets a time in it.
  Shutter shutter;
};

}  // namespace rtpro
