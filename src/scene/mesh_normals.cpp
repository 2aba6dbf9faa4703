#include "rtpro/scene/mesh_normals.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <cmath>

namespace rtpro {

namespace {

// Adds each triangle's area-weighted normal to its three vertices, in triangle order.
void accumulate(const std::vector<PaddedVertex>& vertices, const TriangleIndices* begin, const TriangleIndices* end,
                std::vector<Vec3>& sums) {
  for (const TriangleIndices* t = begin; t != end; ++t) {
    const Vec3 p0 = vertices[t->v0].position();
    // The unnormalised cross product is twice the area times the unit normal: area weighting
    // comes for free.
    const Vec3 weighted = cross(vertices[t->v1].position() - p0, vertices[t->v2].position() - p0);
    sums[t->v0] += weighted;
    sums[t->v1] += weighted;
    sums[t->v2] += weighted;
  }
}

}  // namespace

Vec3 unit_or(const Vec3& v, const Vec3& fallback) {
  const float largest = max_component(abs(v));
  if (!(largest > 0.0f) || !std::isfinite(largest)) return fallback;
  const Vec3 scaled = v / largest;
  return scaled / length(scaled);
}

std::vector<Vec3> area_weighted_vertex_normals(const std::vector<PaddedVertex>& vertices,
                                               const std::vector<TriangleIndices>& triangles) {
  // Two fixed halves of the triangle list sum into separate arrays on two cores; the halves are
  // added in a fixed order, so the result never depends on the number of threads.
  const TriangleIndices* begin = triangles.data();
  const TriangleIndices* middle = begin + triangles.size() / 2;
  std::vector<Vec3> normals(vertices.size(), Vec3(0.0f));
  std::vector<Vec3> second_half(vertices.size(), Vec3(0.0f));
  tbb::parallel_invoke([&] { accumulate(vertices, begin, middle, normals); },
                       [&] { accumulate(vertices, middle, begin + triangles.size(), second_half); });
  tbb::parallel_for(std::size_t(0), normals.size(), [&](std::size_t i) {
    normals[i] = unit_or(normals[i] + second_half[i], Vec3(0.0f, 0.0f, 1.0f));
  });
  return normals;
}

}  // namespace rtpro
