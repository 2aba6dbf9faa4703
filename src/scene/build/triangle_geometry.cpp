#include "rtpro/scene/triangle_geometry.h"

#include "rtpro/scene/scene_summary.h"

#include <algorithm>

namespace rtpro {

std::uint32_t primitive_count_of(const TriangleMesh& mesh) { return static_cast<std::uint32_t>(mesh.triangles.size()); }

BBox primitive_bounds_of(const TriangleMesh& mesh, std::uint32_t prim) { return mesh.triangle_bounds(prim); }

BBox primitive_bounds_at_step(const TriangleMesh& mesh, std::uint32_t prim, std::uint32_t step) {
  const TriangleIndices& tri = mesh.triangles[prim];
  const VertexArray& vertices = mesh.vertex_steps[step];
  BBox b;
  for (std::uint32_t v : {tri.v0, tri.v1, tri.v2}) b.extend(vertices[v].position());
  return b;
}

BBox bounds_of(const TriangleMesh& mesh) { return mesh.bounds(); }

void tally_shapes(const TriangleMesh& mesh, ShapeTally& tally, SceneSummary& summary) {
  ++summary.meshes;
  tally.triangles += mesh.triangles.size();
  summary.vertices_stored += mesh.vertices.size();
  summary.geometry_bytes += mesh.memory_bytes();
  tally.primitives += mesh.triangles.size();
  if (mesh.moving()) {
    ++summary.motion.deforming_meshes;
    summary.motion.vertex_steps = std::max(summary.motion.vertex_steps, mesh.vertex_steps.size());
    // The native BVH keeps the triangles' rows per step and a 64-byte node with linear bounds.
    summary.estimated_bvh_bytes += mesh.triangles.size() * (36 * (mesh.vertex_steps.size() - 1) + 64);
  }
}

}  // namespace rtpro
