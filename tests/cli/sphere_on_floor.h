#pragma once
// For the command-line tests: a scene that renders in moments, a sphere on a floor under a point
// light, for tests of the command line rather than of the picture.
#include <string>

namespace rtpro::test {

// `width` × `height` pixels, 4 samples a pixel, two bounces, seed 3.
inline std::string sphere_on_floor_scene(int width = 24, int height = 16) {
  return "rtpro: 1\n"
         "camera: {position: [0, 1, 6], look_at: [0, 0.5, 0], fov: 40, resolution: [" +
         std::to_string(width) + ", " + std::to_string(height) +
         "]}\n"
         "render: {spp: 4, max_depth: 2, seed: 3}\n"
         "lights:\n"
         "  - {type: point, position: [4, 6, 5], intensity: 1}\n"
         "world:\n"
         "  - {type: sphere, center: [0, -1000, 0], radius: 1000}\n"
         "  - {type: sphere, center: [0, 0.7, 0], radius: 0.7}\n";
}

}  // namespace rtpro::test
