#include "triangle_leaves.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <variant>

namespace rtpro {

TriangleLeaves build_triangle_leaves(const Group& group, const Bvh& bvh, bool enabled) {
  TriangleLeaves leaves;
  leaves.triangle_leaf.assign(bvh.nodes.size(), 0);
  if (!enabled || bvh.refs.empty()) return leaves;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bvh.nodes.size(), 4096), [&](const auto& range) {
    for (std::size_t n = range.begin(); n < range.end(); ++n) {
      const BvhNode& node = bvh.nodes[n];
      if (!node.is_leaf()) continue;
      bool triangles = true;
      // A deforming mesh's triangles are tested one by one at each ray's time, not from rows.
      for (std::uint32_t i = 0; i < node.count; ++i) {
        const auto* mesh = std::get_if<TriangleMesh>(&group.geometries[bvh.refs[node.index + i].geom]);
        triangles &= mesh != nullptr && !mesh->moving();
      }
      leaves.triangle_leaf[n] = triangles;
    }
  });
  // A tree without a triangle leaf (spheres and instances alone) needs no rows.
  if (std::find(leaves.triangle_leaf.begin(), leaves.triangle_leaf.end(), 1) == leaves.triangle_leaf.end())
    return leaves;
  // Three zero columns past the last reference: a leaf's last four-column load stays inside.
  leaves.stride = bvh.refs.size() + kBlockWidth - 1;
  leaves.vertices.assign(9 * leaves.stride, 0.0f);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bvh.refs.size(), 4096), [&](const auto& range) {
    for (std::size_t r = range.begin(); r < range.end(); ++r) {
      const TriangleMesh* mesh = std::get_if<TriangleMesh>(&group.geometries[bvh.refs[r].geom]);
      if (mesh == nullptr) continue;
      const TriangleIndices& tri = mesh->triangles[bvh.refs[r].prim];
      const Vec3 p[3] = {mesh->vertex(tri.v0), mesh->vertex(tri.v1), mesh->vertex(tri.v2)};
      for (int vertex = 0; vertex < 3; ++vertex)
        for (int c = 0; c < 3; ++c) leaves.vertices[(3 * vertex + c) * leaves.stride + r] = p[vertex][c];
    }
  });
  return leaves;
}

}  // namespace rtpro
