#include "gltf_asset.h"

namespace rtpro {

std::string gltf_node_path(std::uint32_t node) { return "nodes[" + std::to_string(node) + "]"; }

BBox GltfAsset::bounds() const {
  std::vector<BBox> mesh_bounds;
  mesh_bounds.reserve(meshes.size());
  for (const TriangleMesh& mesh : meshes) {
    BBox b;
    // Only vertices triangles use: a mesh may carry vertices of skipped primitives.
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) b.extend(mesh.triangle_bounds(t));
    mesh_bounds.push_back(b);
  }
  BBox world;
  for (const GltfPlacement& p : placements)
    if (!mesh_bounds[p.mesh].empty()) world.extend(p.transform.apply(mesh_bounds[p.mesh]));
  return world;
}

}  // namespace rtpro
