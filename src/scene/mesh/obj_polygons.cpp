// A chunk's polygons (faces of more than three corners), triangulated once every position in
// the file is known: a face may use positions that later lines define.
#include "mesh_triangulation.h"
#include "obj_chunk.h"

#include <vector>

namespace rtpro::obj {

void triangulate_polygons(Chunk& chunk, const VertexArray& positions) {
  std::vector<Vec3> points;
  std::vector<LocalTriangle> local;
  const bool normals = chunk.every_corner_has_normal, texcoords = chunk.every_corner_has_texcoord;
  for (const Polygon& polygon : chunk.polygons) {
    const Corner* corners = chunk.polygon_corners.data() + polygon.first_corner;
    points.clear();
    local.clear();
    for (std::uint32_t k = 0; k < polygon.corner_count; ++k)
      points.push_back(positions[corners[k].position].position());
    const PolygonTriangulation result = triangulate_polygon(points, local);
    chunk.concave_polygons += result.concave;
    if (result.fan_fallback && chunk.fan_fallback_line == 0) chunk.fan_fallback_line = polygon.line;
    chunk.dropped_degenerate += result.dropped;
    std::uint32_t kept = 0;
    for (const LocalTriangle& t : local) {
      const Corner &a = corners[t[0]], &b = corners[t[1]], &c = corners[t[2]];
      if (a.position == b.position || b.position == c.position || a.position == c.position) {
        ++chunk.dropped_degenerate;
        continue;
      }
      chunk.polygon_triangles.push_back({a.position, b.position, c.position});
      if (normals) chunk.polygon_triangle_normals.push_back({a.normal, b.normal, c.normal});
      if (texcoords) chunk.polygon_triangle_texcoords.push_back({a.texcoord, b.texcoord, c.texcoord});
      ++kept;
    }
    chunk.triangles_of_polygon.push_back(kept);
  }
  chunk.polygon_corners = {};
}

}  // namespace rtpro::obj
