// The README and scenes/FORMAT.md name every shipped scene, so their lists cannot go stale again.
#include "test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace rtpro {
namespace shipped_scene_docs_test {

TEST(ShippedSceneDocs, ReadmeAndFormatNameEveryShippedScene) {
  const std::string readme = test::read_file(test::source_dir() / "README.md");
  const std::string format = test::read_file(test::scenes_dir() / "FORMAT.md");
  ASSERT_FALSE(readme.empty());
  ASSERT_FALSE(format.empty());
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::scenes_dir())) {
    const std::string extension = entry.path().extension().string();
    if (extension != ".yaml" && extension != ".gltf") continue;
    ++scenes;
    const std::string name = "`" + entry.path().filename().string() + "`";
    EXPECT_NE(readme.find(name), std::string::npos) << name << " is not named in README.md";
    EXPECT_NE(format.find(name), std::string::npos) << name << " is not named in scenes/FORMAT.md";
  }
  EXPECT_GE(scenes, 10);
}

}  // namespace shipped_scene_docs_test
}  // namespace rtpro
