#include "rtpro/scene/scene_inputs.h"

#include <set>

namespace rtpro {

std::vector<SceneInput> scene_inputs(const SceneDescription& description, const SceneBuildReport& report,
                                     const RenderScene& scene) {
  std::vector<SceneInput> inputs;
  std::set<std::filesystem::path> seen;
  const auto add = [&](const char* kind, const std::filesystem::path& file) {
    if (!file.empty() && seen.insert(file).second) inputs.push_back({kind, file});
  };
  for (const auto& file : description.source_files) add("scene", file);
  for (const SceneBuildReport::MeshFile& mesh : report.meshes) {
    add("mesh", mesh.file);
    for (const auto& file : mesh.stats.files_read) add("mesh data", file);
  }
  if (scene.environment) add("environment", scene.environment->file);
  for (const TextureImage& texture : scene.textures)
    if (!texture.bytes) add("texture", texture.file);
  return inputs;
}

}  // namespace rtpro
