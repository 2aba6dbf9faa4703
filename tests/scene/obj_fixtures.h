#pragma once
// For the scene module's OBJ tests: a unit cube, and what a loaded mesh says of its corners and
// in its warnings.
#include "rtpro/scene/mesh_loader.h"

#include <cstdint>
#include <string>

namespace rtpro::test {

// The eight corners of the unit cube [0, 1]³.
inline constexpr const char* kCubePositions = R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
)";
// Outward-facing quads: -z, +z, -y, +x, +y, -x.
inline constexpr const char* kCubeFaces = "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

// The normal at corner `corner` (0, 1 or 2) of triangle `triangle`.
inline Vec3 corner_normal(const TriangleMesh& mesh, std::uint32_t triangle, int corner) {
  const TriangleIndices& t = mesh.triangles[triangle];
  return mesh.normals[corner == 0 ? t.v0 : corner == 1 ? t.v1 : t.v2];
}

inline bool has_warning_containing(const MeshLoadStats& stats, const std::string& text) {
  for (const std::string& w : stats.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace rtpro::test
