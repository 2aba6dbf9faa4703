#pragma once
// Triangulating the polygons of OBJ and PLY faces. Convex polygons become a fan; concave ones are
// ear-clipped in the plane of the polygon, so a ring written as one keyhole polygon (outer
// boundary, a bridge, the hole the other way round, back along the bridge) keeps its hole.
#include "rtpro/core/vec3.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

// Ear clipping costs O(n^2) and more for a polygon of n corners. Above this many corners a
// concave polygon is fan-triangulated instead (with a warning), so a hostile one-line polygon
// cannot take minutes; real files' polygons are far smaller.
inline constexpr std::size_t kMaxEarClippedCorners = 1024;

using LocalTriangle = std::array<std::uint32_t, 3>;  // indices into the polygon's corners

struct PolygonTriangulation {
  bool concave = false;       // ear clipping was needed
  bool fan_fallback = false;  // concave but too large, self-intersecting or not planar enough
                              // for ear clipping: fan-triangulated (maybe wrongly)
  std::size_t dropped = 0;    // of the n - 2 triangles, those with zero area (not emitted)
};

// Appends the triangles of the polygon with these corners (in order, either orientation) to
// `out`, each in the polygon's own winding. Triangles of zero area are left out and counted.
PolygonTriangulation triangulate_polygon(std::span<const Vec3> corners, std::vector<LocalTriangle>& out);

}  // namespace rtpro
