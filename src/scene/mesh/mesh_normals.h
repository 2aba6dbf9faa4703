#pragma once
// Per-vertex normals for loaded meshes.
#include "rtpro/core/vec3.h"
#include "rtpro/scene/mesh.h"

#include <vector>

namespace rtpro {

// v scaled to unit length, or `fallback` when v is zero or not finite. Huge vectors (|v|^2 beyond
// float range) and tiny ones still normalise.
Vec3 unit_or(const Vec3& v, const Vec3& fallback);

// Smooth normals: each vertex gets the area-weighted mean of the normals of the triangles using
// it. Vertices used by no triangle, or only by zero-area ones, get +z. Each vertex sums its
// triangles in triangle order, so the result depends on nothing but the arrays, not on the number
// of threads.
std::vector<Vec3> area_weighted_vertex_normals(const std::vector<PaddedVertex>& vertices,
                                               const std::vector<TriangleIndices>& triangles);

}  // namespace rtpro
