#pragma once
// Settings that change how a scene is rendered rather than what it holds; the scene file's
// `render:` block. Shared by the description and the render scene.
#include "rtpro/core/vec3.h"

#include <cstdint>

namespace rtpro {

struct RenderSettings {
  int spp = 16;        // samples per pixel, 1..65536 (stratified over the most nearly square grid)
  int max_depth = 5;   // mirror bounces after the camera ray
  std::uint64_t seed = 0;
  float ambient = 0.2f;
  Color background{0.0f, 0.0f, 0.0f};
};

}  // namespace rtpro
