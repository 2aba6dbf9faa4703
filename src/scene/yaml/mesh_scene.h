#pragma once
// An OBJ or PLY file as the whole scene (`rtpro render model.obj`; model_scene.h has what every
// model format shares): the mesh in the world with its own MTL materials (or the scene's default),
// a camera framing its bounds, and a default light unless an MTL material emits. The mesh is
// loaded once, here, for its bounds, and handed to the build.
#include "rtpro/scene/description.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro {

// Whether the file is read as a mesh scene: .obj or .ply, in any case.
bool is_mesh_scene_file(const std::filesystem::path& file);

SceneDescription parse_mesh_scene_file(const std::filesystem::path& file, const std::vector<std::string>& overrides);

}  // namespace rtpro
