#pragma once
// Scenes may use meshes that are too large to commit (e.g. the Stanford dragon under assets/);
// a fetch script downloads them. Such a scene cannot be rendered on a fresh clone, and that is
// not a regression: the test skips it and names the script that provides the file. A mesh that
// no fetch script provides is a broken scene and must fail instead.
//
// The scene's YAML is scanned here, before parse_scene_file, because the parser rejects a missing
// mesh file as an input error like any other: this only tells the two kinds of missing apart.
#include "test_paths.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rtpro::regression {

struct MissingMesh {
  std::filesystem::path file;                         // as resolved against the scene's folder
  std::optional<std::filesystem::path> fetch_script;  // the scripts/fetch-*.sh that names it
};

namespace detail {

inline void collect_mesh_files(const YAML::Node& node, std::vector<std::string>& files) {
  if (node.IsSequence()) {
    for (const YAML::Node& item : node) collect_mesh_files(item, files);
  } else if (node.IsMap()) {
    const YAML::Node type = node["type"];
    const YAML::Node file = node["file"];
    if (type && type.IsScalar() && type.Scalar() == "mesh" && file && file.IsScalar()) files.push_back(file.Scalar());
    for (const auto& entry : node) collect_mesh_files(entry.second, files);
  }
}

// The first fetch script (by name) whose text mentions the file's name.
inline std::optional<std::filesystem::path> fetch_script_for(const std::filesystem::path& mesh,
                                                             const std::filesystem::path& scripts_dir) {
  std::vector<std::filesystem::path> scripts;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(scripts_dir, error)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("fetch-") && entry.path().extension() == ".sh") scripts.push_back(entry.path());
  }
  std::sort(scripts.begin(), scripts.end());
  for (const auto& script : scripts)
    if (test::read_file(script).find(mesh.filename().string()) != std::string::npos) return script;
  return std::nullopt;
}

}  // namespace detail

// Mesh files the scene names that do not exist. A scene that is not valid YAML yields nothing
// here; parse_scene_file reports it properly.
inline std::vector<MissingMesh> missing_meshes(const std::filesystem::path& scene_file,
                                               const std::filesystem::path& scripts_dir) {
  std::vector<std::string> files;
  try {
    detail::collect_mesh_files(YAML::LoadFile(scene_file.string()), files);
  } catch (const YAML::Exception&) {
    return {};
  }
  std::vector<MissingMesh> missing;
  for (const std::string& name : files) {
    std::filesystem::path file = name;
    if (file.is_relative()) file = scene_file.parent_path() / file;
    file = file.lexically_normal();
    if (!std::filesystem::exists(file)) missing.push_back({file, detail::fetch_script_for(file, scripts_dir)});
  }
  return missing;
}

}  // namespace rtpro::regression
