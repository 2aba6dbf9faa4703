#pragma once
// Loading glTF 2.0 files (.gltf with its .bin files, or .glb) through tinygltf, Debian's
// libtinygltf-dev, into a GltfAsset.
// - tinygltf parses the JSON and the GLB container and decodes data URIs. It decodes no images:
//   an image loader that keeps nothing is installed, and textures are recorded by reference
//   (gltf_material.h) for OpenImageIO to read when texturing arrives.
// - Files it reads (buffers, images) must be inside the glTF's folder, after resolving symbolic
//   links; tinygltf would otherwise also look in the current directory.
// - Before tinygltf sees the JSON, its nesting is capped at kMaxGltfJsonDepth (tinygltf turns
//   `extras` into its own values recursively), and files of 4 GiB or more are refused.
// - glTF 1.0 files are refused; so are files requiring an extension that changes how geometry is
//   stored (Draco, meshopt, quantization); other required extensions are a warning.
// - Everything tinygltf does not check is checked here (gltf_accessor.h, gltf_nodes.h), and every
//   error is an InputError naming the file and the JSON path of the offending element.
#include "gltf_asset.h"

#include <cstdint>
#include <filesystem>
#include <memory>

namespace rtpro {

inline constexpr int kMaxGltfJsonDepth = 128;

GltfAsset load_gltf_file(const std::filesystem::path& file, const MeshLoadOptions& options = {});

// The nodes of the file that draw a mesh, from its JSON alone (no buffer read): at most the
// placements load_gltf_file makes, since nodes form trees. For the memory estimate before the
// file is loaded; 1 when the file cannot be read (the loader reports why later).
std::uint64_t count_gltf_mesh_nodes(const std::filesystem::path& file);

// Whether the file name ends in .gltf or .glb (case-insensitive).
bool is_gltf_file(const std::filesystem::path& file);

}  // namespace rtpro
