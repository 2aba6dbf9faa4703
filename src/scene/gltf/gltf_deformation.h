#pragma once
// What deforms one glTF mesh (all its primitives, merged as gltf_mesh.h merges them): its morph
// targets and skin weights per vertex of the merged mesh, and the mesh posed with given weights
// and joint matrices.
#include "gltf_morph.h"
#include "gltf_skin.h"
#include "rtpro/scene/mesh.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace rtpro::gltf {

struct MeshDeformation {
  std::vector<MorphTarget> targets;     // per vertex of the merged mesh
  std::vector<double> default_weights;  // the mesh's `weights`, one per target (0 when it gives none)
  SkinWeights skin;                     // per vertex, or empty: no primitive is skinned
  // Triangles whose vertices are their own and carry its face normal (primitives without NORMAL in
  // a mesh with normals): the face normal is recomputed after deformation.
  std::vector<std::uint32_t> flat_triangles;
  bool smooth_normals = false;  // normals: smooth: recomputed area-weighted after deformation
  // The largest joint index of the skin weights, and the attribute naming it, which the skin of
  // every node drawing the mesh must have.
  std::uint32_t max_joint = 0;
  std::string max_joint_path;

  bool morphs() const { return !targets.empty(); }
  bool skinned() const { return !skin.joints.empty(); }
};

// `mesh` with morph `weights` (one per target) applied, then the skin's `joints` matrices (none:
// unskinned). Throws InputError naming `where` when a posed vertex leaves the supported range.
TriangleMesh deform_mesh(const TriangleMesh& mesh, const MeshDeformation& deformation, std::span<const double> weights,
                         const std::vector<Affine>* joints, const std::string& file, const std::string& where);

}  // namespace rtpro::gltf
