#pragma once
// Reads a scene's `objects:` and `world:` (spheres, meshes, instances) into a SceneDescription
// whose materials and lights are already read, resolving names to indices (light names of the
// world entries' light linking too) and checking the instance graph for cycles and nesting depth.
#include "rtpro/scene/description.h"
#include "yaml_document.h"
#include "yaml_motion.h"

#include <cstddef>
#include <filesystem>

namespace rtpro {

// Instances may nest this deep (an instance in the world is level 1).
inline constexpr int kMaxInstanceNesting = 16;
// Entries (shapes and instances) in all objects and the world together; anchors and aliases
// could otherwise make a small file describe an enormous scene.
inline constexpr std::size_t kMaxSceneEntries = std::size_t{1} << 24;

// Either node may be null (absent). Mesh paths are resolved against `folder` and must exist.
// `motion`: how keyframed transforms and sphere centres are read at the shutter's time steps.
void read_scene_objects(const YamlNode* objects, const YamlNode* world, const std::filesystem::path& folder,
                        const YamlMotion& motion, SceneDescription& scene);

}  // namespace rtpro
