#pragma once
// The JSON types of the glTF properties rtpro reads, checked before tinygltf sees the file.
// tinygltf skips a property of the wrong type without a word (`"primitives": {}` gives a mesh
// without triangles, `"index": -1` a material without its texture), so a mistyped file would
// render wrong with exit 0; here it is refused, naming the property's JSON path.
#include <string>
#include <string_view>

namespace rtpro::gltf {

// Throws InputError naming `file` and the first mistyped property ("meshes[0].primitives: an
// array expected, found an object"). JSON that does not parse is left to tinygltf's message.
void check_json_types(std::string_view json_text, const std::string& file);

}  // namespace rtpro::gltf
