#pragma once
// Which world coordinates a checkerboard's squares follow, shared by the scene description and
// the render scene.
#include <cstdint>

namespace rtpro {

// A plane's two axes (squares seen along the third axis, so a ground plane at y = 0 needs no
// offset against rounding), or all three (a solid of cubes).
enum class CheckerAxes : std::uint8_t { kXZ, kXY, kYZ, kXYZ };

}  // namespace rtpro
