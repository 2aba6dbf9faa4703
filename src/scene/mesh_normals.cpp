#include "rtpro/scene/mesh_normals.h"

#include <cmath>

namespace rtpro {

Vec3 unit_or(const Vec3& v, const Vec3& fallback) {
  const float largest = max_component(abs(v));
  if (!(largest > 0.0f) || !std::isfinite(largest)) return fallback;
  const Vec3 scaled = v / largest;
  return scaled / length(scaled);
}

std::vector<Vec3> area_weighted_vertex_normals(const std::vector<PaddedVertex>& vertices,
                                               const std::vector<TriangleIndices>& triangles) {
  std::vector<Vec3> normals(vertices.size(), Vec3(0.0f));
  for (const TriangleIndices& t : triangles) {
    const Vec3 p0 = vertices[t.v0].position();
    // The unnormalised cross product is twice the area times the unit normal: area weighting
    // comes for free.
    const Vec3 weighted = cross(vertices[t.v1].position() - p0, vertices[t.v2].position() - p0);
    normals[t.v0] += weighted;
    normals[t.v1] += weighted;
    normals[t.v2] += weighted;
  }
  for (Vec3& n : normals) n = unit_or(n, Vec3(0.0f, 0.0f, 1.0f));
  return normals;
}

}  // namespace rtpro
