#include "mesh_normals.h"

#include "rtpro/core/large_buffer.h"

#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
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

std::string repaired_normals_warning(const std::string& file, std::size_t repaired) {
  return file + ": " + std::to_string(repaired) + (repaired == 1 ? " vertex normal is" : " vertex normals are") +
         " zero or not finite; replaced by the normals of the faces around " + (repaired == 1 ? "it" : "them");
}

std::vector<Vec3> area_weighted_vertex_normals(const VertexArray& vertices,
                                               const std::vector<TriangleIndices>& triangles) {
  std::vector<Vec3> normals;
  resize_large(normals, vertices.size());
  // Each task owns a range of vertices and walks every triangle, adding only to its own vertices.
  // So every vertex sums its triangles in triangle order, exactly as one serial loop would, however
  // many tasks share the work, and no task needs memory of its own.
  const std::size_t tasks = std::size_t(std::max(1, tbb::this_task_arena::max_concurrency()));
  const auto sum_and_normalise = [&](std::size_t task) {
    const std::size_t first = vertices.size() * task / tasks;
    const std::size_t count = vertices.size() * (task + 1) / tasks - first;
    const auto owned = [first, count](std::uint32_t v) { return v - first < count; };
    for (const TriangleIndices& t : triangles) {
      const bool own0 = owned(t.v0), own1 = owned(t.v1), own2 = owned(t.v2);
      if (!(own0 || own1 || own2)) continue;
      const Vec3 p0 = vertices[t.v0].position();
      // The unnormalised cross product is twice the area times the unit normal: area weighting
      // comes for free.
      const Vec3 weighted = cross(vertices[t.v1].position() - p0, vertices[t.v2].position() - p0);
      if (own0) normals[t.v0] += weighted;
      if (own1) normals[t.v1] += weighted;
      if (own2) normals[t.v2] += weighted;
    }
    for (std::size_t v = first; v < first + count; ++v) normals[v] = unit_or(normals[v], Vec3(0.0f, 0.0f, 1.0f));
  };
  tbb::parallel_for(std::size_t(0), tasks, sum_and_normalise, tbb::static_partitioner());
  return normals;
}

}  // namespace rtpro
