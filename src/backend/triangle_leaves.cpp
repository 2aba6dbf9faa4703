#include "triangle_leaves.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <variant>

namespace rtpro {

namespace {

// The mesh behind reference `r`, or nothing where it is not a triangle.
const TriangleMesh* mesh_of(const Group& group, const Bvh& bvh, std::size_t r) {
  return std::get_if<TriangleMesh>(&group.geometries[bvh.refs[r].geom]);
}

// Writes reference r's triangle with corners p into the nine rows from `rows`.
void write_column(float* rows, std::size_t stride, std::size_t r, const Vec3 (&p)[3]) {
  for (int vertex = 0; vertex < 3; ++vertex)
    for (int c = 0; c < 3; ++c) rows[(3 * vertex + c) * stride + r] = p[vertex][c];
}

}  // namespace

TriangleLeaves build_triangle_leaves(const Group& group, const Bvh& bvh, bool enabled) {
  TriangleLeaves leaves;
  leaves.triangle_leaf.assign(bvh.nodes.size(), 0);
  if (!enabled || bvh.refs.empty()) return leaves;
  for (const Geometry& geometry : group.geometries)
    if (const auto* mesh = std::get_if<TriangleMesh>(&geometry); mesh != nullptr && mesh->moving()) {
      leaves.motion_steps = static_cast<std::uint32_t>(mesh->vertex_steps.size());
      break;
    }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bvh.nodes.size(), 4096), [&](const auto& range) {
    for (std::size_t n = range.begin(); n < range.end(); ++n) {
      const BvhNode& node = bvh.nodes[n];
      if (!node.is_leaf()) continue;
      bool still = true, moving = true;
      for (std::uint32_t i = 0; i < node.count; ++i) {
        const TriangleMesh* mesh = mesh_of(group, bvh, node.index + i);
        still &= mesh != nullptr && !mesh->moving();
        moving &= mesh != nullptr && mesh->moving() && mesh->vertex_steps.size() == leaves.motion_steps;
      }
      leaves.triangle_leaf[n] = still ? kStillRows : moving ? kMovingRows : 0;
    }
  });
  const auto has = [&](std::uint8_t rows) {
    return std::find(leaves.triangle_leaf.begin(), leaves.triangle_leaf.end(), rows) != leaves.triangle_leaf.end();
  };
  const bool still_rows = has(kStillRows), moving_rows = has(kMovingRows);
  // A tree without a triangle leaf (spheres and instances alone) needs no rows.
  if (!still_rows && !moving_rows) return leaves;
  // Three zero columns past the last reference: a leaf's last four-column load stays inside.
  leaves.stride = bvh.refs.size() + kBlockWidth - 1;
  if (still_rows) leaves.vertices.assign(9 * leaves.stride, 0.0f);
  if (moving_rows) leaves.motion_vertices.assign(std::size_t{leaves.motion_steps} * 9 * leaves.stride, 0.0f);
  else leaves.motion_steps = 0;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bvh.refs.size(), 4096), [&](const auto& range) {
    for (std::size_t r = range.begin(); r < range.end(); ++r) {
      const TriangleMesh* mesh = mesh_of(group, bvh, r);
      if (mesh == nullptr) continue;
      const TriangleIndices& tri = mesh->triangles[bvh.refs[r].prim];
      if (!mesh->moving()) {
        if (still_rows)
          write_column(leaves.vertices.data(), leaves.stride, r,
                       {mesh->vertex(tri.v0), mesh->vertex(tri.v1), mesh->vertex(tri.v2)});
        continue;
      }
      if (mesh->vertex_steps.size() != leaves.motion_steps) continue;
      for (std::uint32_t step = 0; step < leaves.motion_steps; ++step) {
        const VertexArray& at = mesh->vertex_steps[step];
        write_column(leaves.motion_vertices.data() + std::size_t{step} * 9 * leaves.stride, leaves.stride, r,
                     {at[tri.v0].position(), at[tri.v1].position(), at[tri.v2].position()});
      }
    }
  });
  return leaves;
}

}  // namespace rtpro
