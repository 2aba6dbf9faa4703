#pragma once
// A glTF file as the whole scene (`rtpro render model.glb`; model_scene.h has what every model
// format shares): the file placed in the world, its first perspective camera or one framing its
// bounds, and its KHR_lights_punctual lights or a default light. A file whose name is not UTF-8
// (which YAML cannot hold) is placed in the world after the text is read.
//
// Animation: the cameras and lights are posed at the frame (description.frame / render.fps
// seconds); the meshes are posed when the scene is built. A framing camera frames the file as it
// stands without animation, the same for every frame.
//
// Lights: glTF intensities are photometric (point and spot lights in candela, directional lights
// in lux) and become radiometric ones at 683 lm/W, as Blender's importer reads them; a spot
// light keeps its cone.
#include "model_scene.h"
#include "rtpro/scene/description.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro {

inline constexpr float kLumensPerWatt = 683.0f;

// The scene of the loaded file `asset`, its cameras and lights where `pose` puts them (the asset
// itself: without animation).
struct GltfAsset;
struct GltfPose;
ModelSceneText gltf_scene_text(const GltfAsset& asset, const GltfPose& pose);

SceneDescription parse_gltf_scene_file(const std::filesystem::path& file, const std::vector<std::string>& overrides);

}  // namespace rtpro
