#pragma once
// A glTF file as the whole scene (`rtpro render model.glb`): the file placed in the world, its
// first perspective camera or a default one framing its bounds, and its KHR_lights_punctual lights
// or a default light. Written as a YAML scene and read by the ordinary parser, so `--set`
// overrides (camera.fov, render.spp, ...) work exactly as for scene files. A file whose name is
// not UTF-8 (which YAML cannot hold) is placed in the world after the text is read.
//
// Lights: glTF intensities are photometric (point and spot lights in candela, directional lights
// in lux) and become radiometric ones at 683 lm/W, as Blender's importer reads them; a spot
// light keeps its cone.
#include "rtpro/scene/description.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro {

// The YAML text of the scene and, line by line, the glTF element each line was written for: an
// error the scene parser finds in the text names that element (its JSON path, e.g.
// "nodes[3] (cameras[1])") and the glTF file, never a line of text the user did not write.
struct GltfSceneText {
  std::string yaml;
  std::vector<std::string> origin_of_line;  // [line - 1]

  void add(const std::string& line, const std::string& origin);
  // What line `line` (1-based) was written for; the scene as a whole past the last line.
  const std::string& origin(int line) const;
};

// The scene of the loaded file `asset`.
struct GltfAsset;
GltfSceneText gltf_scene_text(const GltfAsset& asset);

SceneDescription parse_gltf_scene_file(const std::filesystem::path& file, const std::vector<std::string>& overrides);

}  // namespace rtpro
