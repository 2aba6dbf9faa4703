#pragma once
// Which texture coordinates a glTF material's textures read, and KHR_texture_transform.
// rtpro's meshes carry one set of texture coordinates and its materials no texture transform, so
// a material's mapping is applied to the coordinates of the primitives that use it when they are
// loaded: TEXCOORD_n for `texCoord: n`, then the transform (offset, rotation, scale). The
// material's base colour texture decides (the other texture slots when it has none); a slot that
// asks for other coordinates or another transform is a warning, since one mapping serves them all.
#include "rtpro/scene/mesh.h"

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace rtpro::gltf {

struct UvMapping {
  int set = 0;            // TEXCOORD_<set>
  bool textured = false;  // whether the material has a texture slot that reads them
  // u' = m[0] u + m[1] v + m[2], v' = m[3] u + m[4] v + m[5], in glTF's texture space (v down).
  double m[6] = {1, 0, 0, 0, 1, 0};
  bool identity() const { return m[0] == 1 && m[1] == 0 && m[2] == 0 && m[3] == 0 && m[4] == 1 && m[5] == 0; }
};

// The mapping of model.materials[material] (the default one for a negative index); warnings name
// the material's slots that disagree with it.
UvMapping uv_mapping(const tinygltf::Model& model, int material, const std::string& file,
                     std::vector<std::string>& warnings);

// Applies `mapping` to coordinates in rtpro's convention (v flipped from glTF's, see
// gltf_accessor.h).
void apply_uv_mapping(const UvMapping& mapping, std::vector<TexCoord>& uvs);

}  // namespace rtpro::gltf
