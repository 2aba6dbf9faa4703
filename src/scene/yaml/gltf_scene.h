#pragma once
// A glTF file as the whole scene (`rtpro render model.glb`): the file placed in the world, its
// first perspective camera or a default one framing its bounds, and its KHR_lights_punctual lights
// or a default light. Written as a YAML scene and read by the ordinary parser, so `--set`
// overrides (camera.fov, render.spp, ...) work exactly as for scene files.
//
// Lights: glTF intensities are physical (point and spot in candela, directional in lux) while
// rtpro's lights are unitless and do not fall off. Each point or spot light becomes the
// illuminance it gives at the centre of the model (candela / distance^2), each directional light
// its lux, and all are scaled together so that the brightest has intensity 1: relative strengths
// are kept, absolute exposure is not. Spot lights become point lights (their cone is dropped,
// with a warning).
#include "rtpro/scene/description.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro {

// The YAML text of the scene; `asset` is the loaded file (tests read the text).
struct GltfAsset;
std::string gltf_scene_yaml(const GltfAsset& asset);

SceneDescription parse_gltf_scene_file(const std::filesystem::path& file, const std::vector<std::string>& overrides);

}  // namespace rtpro
