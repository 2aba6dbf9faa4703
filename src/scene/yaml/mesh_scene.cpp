#include "mesh_scene.h"

#include "model_scene.h"
#include "rtpro/scene/mesh_loader.h"

#include <algorithm>
#include <cctype>
#include <memory>

namespace rtpro {

bool is_mesh_scene_file(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".obj" || extension == ".ply";
}

SceneDescription parse_mesh_scene_file(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  auto loaded = std::make_shared<LoadedMesh>(load_mesh_file(file));
  const BBox bounds = loaded->mesh.bounds();
  const bool emits = std::any_of(loaded->materials.begin(), loaded->materials.end(),
                                 [](const MaterialDesc& m) { return max_component(m.emission) > 0.0f; });
  ModelSceneText text;
  add_model_header(file, text);
  add_framing_camera(bounds, "the camera rtpro places to frame the mesh (a mesh file has no camera)", text);
  add_model_lighting(emits, text);
  const std::string name = file.filename().string();
  if (writable_in_yaml(name)) {
    text.add("world:", "the file itself, the world's mesh");
    text.add("  - {type: mesh, file: " + quoted_yaml(name) + "}", "the file itself, the world's mesh");
  }
  SceneDescription description = parse_model_scene({.text = text,
                                                    .materials = &loaded->materials,
                                                    .has_camera = false,
                                                    .bounds = bounds,
                                                    .has_lights = false,
                                                    .emits = emits},
                                                   file, overrides);
  // The entry the text wrote takes the mesh already loaded, unless an override asks it to be
  // read otherwise (other normals); a name YAML cannot hold (not UTF-8) is placed here instead.
  bool placed = false;
  for (MeshDesc& mesh : description.world.meshes) {
    if (mesh.file != file.lexically_normal()) continue;
    placed = true;
    mesh.where = SourceLocation{file.string()};
    if (mesh.normals == NormalsMode::kAuto) mesh.loaded = loaded;
  }
  if (!placed && !writable_in_yaml(name))
    description.world.meshes.push_back(
        {file.lexically_normal(), kNoMaterial, SourceLocation{file.string()}, NormalsMode::kAuto, kNoLinking, loaded});
  return description;
}

}  // namespace rtpro
