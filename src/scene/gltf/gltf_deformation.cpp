#include "gltf_deformation.h"

#include "rtpro/core/error.h"
#include "mesh_limits.h"
#include "mesh_normals.h"

#include <cmath>

namespace rtpro::gltf {

TriangleMesh deform_mesh(const TriangleMesh& mesh, const MeshDeformation& deformation, std::span<const double> weights,
                         const std::vector<Affine>* joints, const std::string& file, const std::string& where) {
  TriangleMesh out = mesh;
  std::vector<Vec3> positions(mesh.vertices.size());
  for (std::size_t v = 0; v < positions.size(); ++v) positions[v] = mesh.vertex(std::uint32_t(v));
  apply_morph(deformation.targets, weights, positions, out.normals);
  if (joints && deformation.skinned()) apply_skin(*joints, deformation.skin, positions, out.normals);
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const Vec3& p = positions[v];
    if (!(std::fabs(p.x) <= kMaxAbsCoordinate && std::fabs(p.y) <= kMaxAbsCoordinate &&
          std::fabs(p.z) <= kMaxAbsCoordinate))
      throw InputError(SourceLocation{file}, where + ": posed vertex " + std::to_string(v) +
                                                 " lies beyond the supported magnitude 1e16 or is not finite");
    out.vertices[v] = {p.x, p.y, p.z};
  }
  if (deformation.smooth_normals) {
    out.normals = area_weighted_vertex_normals(out.vertices, out.triangles);
  } else if (!out.normals.empty()) {
    for (const std::uint32_t t : deformation.flat_triangles) {
      const TriangleIndices& tri = out.triangles[t];
      const Vec3 face =
          unit_or(cross(positions[tri.v1] - positions[tri.v0], positions[tri.v2] - positions[tri.v0]), Vec3(0, 0, 1));
      out.normals[tri.v0] = out.normals[tri.v1] = out.normals[tri.v2] = face;
    }
  }
  return out;
}

}  // namespace rtpro::gltf
