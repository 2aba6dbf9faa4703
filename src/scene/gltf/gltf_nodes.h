#pragma once
// Internals of the glTF loader: the node hierarchy of the chosen scene resolved to world
// placements of meshes, cameras and KHR_lights_punctual lights.
// - The scene: `scene` when given, else scenes[0]; a file without scenes places every root node
//   (with a warning).
// - Local transforms: `matrix` (column-major, must be affine) or translation, rotation (a unit
//   quaternion x, y, z, w; normalised) and scale, applied scale first; values must be finite.
// - Validated as trees: every index in range, no node the child of two parents or listed twice
//   as a root, no cycle (`nodes[2].children[0]: node 0 is its own ancestor`), at most
//   kMaxGltfNodeDepth levels. Checked with an explicit stack, so a hostile file cannot overflow
//   the C++ stack either.
// - A node whose world transform is singular (scale 0, which hides parts) places nothing; one
//   warning counts them.
#include "gltf_asset.h"
#include "gltf_accessor.h"

#include <tiny_gltf.h>

namespace rtpro::gltf {

inline constexpr std::size_t kMaxGltfNodeDepth = 1024;

// Fills asset.placements, cameras and lights (mesh indices are the file's).
void place_nodes(const tinygltf::Model& model, const AccessorReader& reader, GltfAsset& asset);

}  // namespace rtpro::gltf
