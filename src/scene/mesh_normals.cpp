#include "rtpro/scene/mesh_normals.h"

#include "rtpro/scene/large_buffer.h"

#include <tbb/parallel_for.h>

#include <cmath>

namespace rtpro {

Vec3 unit_or(const Vec3& v, const Vec3& fallback) {
  const float squared = dot(v, v);
  if (squared > 1e-30f && squared < 1e30f) return v * (1.0f / std::sqrt(squared));
  // Tiny, huge or not finite: scale by the largest component first, so the square cannot
  // underflow or overflow.
  const float largest = max_component(abs(v));
  if (!(largest > 0.0f) || !std::isfinite(largest)) return fallback;
  const Vec3 scaled = v / largest;
  return scaled / length(scaled);
}

std::vector<Vec3> area_weighted_vertex_normals(const std::vector<PaddedVertex>& vertices,
                                               const std::vector<TriangleIndices>& triangles) {
  std::vector<Vec3> normals;
  resize_large(normals, vertices.size());
  // One serial pass: the scattered additions are cheap next to the parse, and summing in triangle
  // order makes every normal independent of the thread count.
  for (const TriangleIndices& t : triangles) {
    const Vec3 p0 = vertices[t.v0].position();
    // The unnormalised cross product is twice the area times the unit normal: area weighting
    // comes for free.
    const Vec3 weighted = cross(vertices[t.v1].position() - p0, vertices[t.v2].position() - p0);
    normals[t.v0] += weighted;
    normals[t.v1] += weighted;
    normals[t.v2] += weighted;
  }
  tbb::parallel_for(std::size_t(0), normals.size(),
                    [&normals](std::size_t v) { normals[v] = unit_or(normals[v], Vec3(0.0f, 0.0f, 1.0f)); });
  return normals;
}

}  // namespace rtpro
