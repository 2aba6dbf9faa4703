#pragma once
// Per-vertex normals for loaded meshes.
#include "rtpro/core/vec3.h"
#include "rtpro/scene/mesh.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rtpro {

// v scaled to unit length, or `fallback` when v is zero or not finite. Huge vectors (|v|^2 beyond
// float range) and tiny ones still normalise.
Vec3 unit_or(const Vec3& v, const Vec3& fallback);

// Smooth normals: each vertex gets the area-weighted mean of the normals of the triangles using
// it. Vertices used by no triangle, or only by zero-area ones, get +z. Each vertex sums its
// triangles in triangle order, so the result depends on nothing but the arrays, not on the number
// of threads.
std::vector<Vec3> area_weighted_vertex_normals(const VertexArray& vertices,
                                               const std::vector<TriangleIndices>& triangles);

// Whether `n` can be a shading normal: finite and not zero.
inline bool usable_normal(const Vec3& n) { return is_finite(n) && (n.x != 0.0f || n.y != 0.0f || n.z != 0.0f); }

// Replaces each of `normals` (one per vertex) that is zero or not finite by the area-weighted
// normal of the triangles using its vertex (+z when they have no area), leaving the others as the
// file gave them: one bad normal must not flatten a whole mesh. `position(v)` is vertex v's
// position. Returns how many were replaced.
template <typename Position>
std::size_t repair_vertex_normals(const Position& position, const std::vector<TriangleIndices>& triangles,
                                  std::vector<Vec3>& normals) {
  std::vector<std::uint32_t> bad;
  for (std::size_t v = 0; v < normals.size(); ++v)
    if (!usable_normal(normals[v])) bad.push_back(std::uint32_t(v));
  if (bad.empty()) return 0;
  for (const std::uint32_t v : bad) normals[v] = Vec3(0.0f, 0.0f, 0.0f);
  const auto is_bad = [&](std::uint32_t v) { return std::binary_search(bad.begin(), bad.end(), v); };
  for (const TriangleIndices& t : triangles) {
    const bool bad0 = is_bad(t.v0), bad1 = is_bad(t.v1), bad2 = is_bad(t.v2);
    if (!(bad0 || bad1 || bad2)) continue;
    const Vec3 p0 = position(t.v0);
    const Vec3 weighted = cross(position(t.v1) - p0, position(t.v2) - p0);
    if (bad0) normals[t.v0] += weighted;
    if (bad1) normals[t.v1] += weighted;
    if (bad2) normals[t.v2] += weighted;
  }
  for (const std::uint32_t v : bad) normals[v] = unit_or(normals[v], Vec3(0.0f, 0.0f, 1.0f));
  return bad.size();
}

// The warning for `repaired` normals of `file` replaced by repair_vertex_normals.
std::string repaired_normals_warning(const std::string& file, std::size_t repaired);

}  // namespace rtpro
