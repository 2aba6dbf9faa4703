#include "gltf_asset.h"

namespace rtpro {

std::string gltf_node_path(std::uint32_t node) { return "nodes[" + std::to_string(node) + "]"; }

namespace {

// Only vertices triangles use: a mesh may carry vertices of skipped primitives.
BBox used_bounds(const TriangleMesh& mesh) {
  BBox b;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) b.extend(mesh.triangle_bounds(t));
  return b;
}

}  // namespace

BBox GltfAsset::bounds(const GltfPose& pose) const {
  std::vector<BBox> mesh_bounds;
  mesh_bounds.reserve(meshes.size());
  for (const TriangleMesh& mesh : meshes) mesh_bounds.push_back(used_bounds(mesh));
  BBox world;
  for (const GltfPlacement& p : pose.placements) {
    const BBox b = p.deformed >= 0 ? used_bounds(pose.deformed[std::size_t(p.deformed)]) : mesh_bounds[p.mesh];
    if (!b.empty()) world.extend(p.transform.apply(b));
  }
  return world;
}

}  // namespace rtpro
