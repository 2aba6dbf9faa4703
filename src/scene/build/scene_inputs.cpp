#include "rtpro/scene/scene_inputs.h"

#include <set>
#include <utility>

namespace rtpro {

namespace {

// Adds each file once (by its spelling), in call order.
class InputList {
 public:
  void add(const char* kind, const std::filesystem::path& file) {
    if (!file.empty() && seen_.insert(file).second) inputs_.push_back({kind, file});
  }
  std::vector<SceneInput> take() { return std::move(inputs_); }

 private:
  std::vector<SceneInput> inputs_;
  std::set<std::filesystem::path> seen_;
};

}  // namespace

std::vector<SceneInput> named_inputs(const SceneDescription& description) {
  InputList inputs;
  for (const auto& file : description.source_files) inputs.add("scene", file);
  const auto add_models = [&](const ObjectDesc& object) {
    for (const MeshDesc& mesh : object.meshes) inputs.add("mesh", mesh.file);
    for (const GltfDesc& gltf : object.gltfs) inputs.add("mesh", gltf.file);
  };
  add_models(description.world);
  for (const ObjectDesc& object : description.objects) add_models(object);
  if (description.environment) inputs.add("environment", description.environment->file);
  for (const MaterialDesc& material : description.materials)
    if (!material.texture_bytes) inputs.add("texture", material.color_texture);
  return inputs.take();
}

std::vector<SceneInput> scene_inputs(const SceneDescription& description, const SceneBuildReport& report,
                                     const RenderScene& scene) {
  InputList inputs;
  for (const auto& file : description.source_files) inputs.add("scene", file);
  for (const SceneBuildReport::MeshFile& mesh : report.meshes) {
    inputs.add("mesh", mesh.file);
    for (const auto& file : mesh.stats.files_read) inputs.add("mesh data", file);
  }
  if (scene.environment) inputs.add("environment", scene.environment->file);
  for (const TextureImage& texture : scene.textures)
    if (!texture.bytes) inputs.add("texture", texture.file);
  return inputs.take();
}

}  // namespace rtpro
