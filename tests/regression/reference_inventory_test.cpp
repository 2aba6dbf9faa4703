// Scenes and references pair up one to one. Checked when the test runs, so it holds even while
// the per-scene cases are still the ones listed before a scene file was added.
#include "fetched_meshes.h"
#include "regression_paths.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace rtpro::regression {
namespace reference_inventory_test {

TEST(RegressionReferences, EverySceneHasAReference) {
  for (const auto& scene : scene_files()) {
    if (!missing_meshes(scene, test::source_dir() / "scripts").empty()) continue;  // its cases say why
    EXPECT_TRUE(std::filesystem::is_regular_file(reference_file(scene)))
        << "no reference for " << source_relative(scene) << ": run " << update_command();
  }
}

TEST(RegressionReferences, EveryReferenceHasAScene) {
  for (const auto& entry : std::filesystem::directory_iterator(references_dir())) {
    if (entry.path().extension() != ".exr") continue;
    const std::vector<std::filesystem::path> scenes = scene_files();
    EXPECT_TRUE(std::any_of(scenes.begin(), scenes.end(),
                            [&](const std::filesystem::path& scene) { return reference_file(scene) == entry.path(); }))
        << source_relative(entry.path()) << " belongs to no scene in scenes/: delete it";
  }
}

}  // namespace reference_inventory_test
}  // namespace rtpro::regression
