#pragma once
// Where a top-level geometry of the render scene came from, for the errors about it: its entry in
// the scene file and, for an instance a glTF file places, the node of that file which places it.
#include "rtpro/core/error.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace rtpro {

// Points into the SceneDescription the scene is built from, which outlives the build.
struct GeometryOrigin {
  const SourceLocation* where;                  // the entry in the scene file
  const std::filesystem::path* gltf = nullptr;  // the glTF file that places it, or null
  std::uint32_t gltf_node = 0;                  // nodes[gltf_node] of that file places it
};

// An InputError at the origin's entry about the geometry: "nodes[3]: message" for a glTF node (with
// the glTF file's name before it when the entry is in another file, a YAML scene placing it).
InputError geometry_error(const GeometryOrigin& origin, const std::string& message);

}  // namespace rtpro
