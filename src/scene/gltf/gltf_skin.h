#pragma once
// glTF skins: a mesh whose vertices follow joints (nodes). Each vertex names up to eight joints of
// the skin (JOINTS_0 and JOINTS_1, four each) with weights (WEIGHTS_0 and WEIGHTS_1); its posed
// position is Σ w_k · J_k · p, where the
// joint matrix J = world(joint) · inverseBindMatrices[k] (the identity when the skin gives none).
// As the specification says, the node drawing a skinned mesh contributes no transform: the posed
// vertices are in the file's world. Weights are normalised to sum 1 (exporters round them); a
// vertex whose weights are all 0 stays where the mesh puts it. Normals follow the inverse
// transpose of the blended joint matrices.
#include "rtpro/core/transform.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace rtpro::gltf {

class AccessorReader;

struct Skin {
  std::vector<std::uint32_t> joints;  // node indices
  std::vector<Affine> inverse_bind;   // one per joint
};

// Joints a vertex follows at most: two sets of four (JOINTS_0/WEIGHTS_0, JOINTS_1/WEIGHTS_1), as
// exporters write for more than four influences (Blender's with its "influences" limit raised).
inline constexpr std::size_t kSkinInfluences = 8;

// Per vertex: its joint indices into a skin's joints and their weights (0 past a primitive's sets).
struct SkinWeights {
  std::vector<std::array<std::uint16_t, kSkinInfluences>> joints;
  std::vector<std::array<float, kSkinInfluences>> weights;
};

// The file's skins: joints that exist, inverse bind matrices that are affine, finite and one per joint.
std::vector<Skin> read_skins(const tinygltf::Model& model, const AccessorReader& reader);

// JOINTS_n and WEIGHTS_n of a primitive of `vertex_count` vertices (each set both or neither, set 1
// only with set 0, no set past 1), or nothing when it has none; weights finite and not negative.
// `path` names the primitive.
SkinWeights read_skin_weights(const tinygltf::Primitive& primitive, std::size_t vertex_count,
                              const AccessorReader& reader, const std::string& path);

// The joint matrices of `skin` with the nodes' world transforms `world`.
std::vector<Affine> joint_matrices(const Skin& skin, const std::vector<Affine>& world);

// Poses positions (and normals, when given) in place.
void apply_skin(const std::vector<Affine>& joints, const SkinWeights& skin, std::span<Vec3> positions,
                std::span<Vec3> normals);

}  // namespace rtpro::gltf
