#pragma once
// Where the regression suite finds scenes and references and leaves its results, and the command
// that regenerates the references.
#include "test_paths.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace rtpro::regression {

// scenes/*.yaml, sorted: every one of them must have a reference.
inline std::vector<std::filesystem::path> scene_files() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(test::scenes_dir()))
    if (entry.path().extension() == ".yaml" || entry.path().extension() == ".gltf") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

inline std::filesystem::path references_dir() { return test::source_dir() / "tests" / "references"; }

// A scene's name in references and test names: its stem for YAML, "cornell_box_gltf" for
// scenes/cornell_box.gltf (a glTF rendered as the whole scene beside a YAML of the same stem).
inline std::string scene_name(const std::filesystem::path& scene) {
  return scene.extension() == ".yaml" ? scene.stem().string()
                                      : scene.stem().string() + "_" + scene.extension().string().substr(1);
}

inline std::filesystem::path reference_file(const std::filesystem::path& scene) {
  return references_dir() / (scene_name(scene) + ".exr");
}

// Failure folders and report.html.
inline std::filesystem::path results_root() { return std::filesystem::path(RTPRO_BINARY_DIR) / "regression"; }

inline std::string update_command() {
  return "cmake --build " + std::string(RTPRO_BINARY_DIR) + " --target update-references";
}

// "scenes/demo.yaml": how messages name files of the source tree.
inline std::string source_relative(const std::filesystem::path& file) {
  return std::filesystem::relative(file, test::source_dir()).generic_string();
}

}  // namespace rtpro::regression
