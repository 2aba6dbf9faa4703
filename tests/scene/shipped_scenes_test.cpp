#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "rtpro/scene/scene_summary.h"

#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace rtpro {
namespace shipped_scenes_test {

std::vector<std::filesystem::path> shipped_scenes() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(test::scenes_dir()))
    if (entry.path().extension() == ".yaml") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(ShippedScenes, EveryYamlFileParses) {
  const auto scenes = shipped_scenes();
  EXPECT_GE(scenes.size(), 4u);
  for (const auto& scene : scenes) {
    SCOPED_TRACE(scene.string());
    if (test::uses_fetched_assets(scene) && !test::fetched_assets_present()) continue;
    EXPECT_NO_THROW(parse_scene_file(scene));
  }
}

TEST(ShippedScenes, DragonFieldHasABillionTrianglesFromOneStoredMesh) {
  if (!test::fetched_assets_present()) GTEST_SKIP() << "run scripts/fetch-dragon.sh to fetch the dragon";
  const RenderScene scene = build_render_scene(parse_scene_file(test::scenes_dir() / "dragon_field.yaml"));
  const SceneSummary summary = summarize(scene);
  EXPECT_GE(summary.triangles_rendered, 1'000'000'000u);
  EXPECT_EQ(summary.triangles_stored, 871'414u);
  EXPECT_EQ(summary.meshes, 1u);
}

TEST(ShippedScenes, DemoIsTheSeedScene) {
  const SceneDescription scene = parse_scene_file(test::scenes_dir() / "demo.yaml");
  EXPECT_EQ(scene.camera.width, 640);
  EXPECT_EQ(scene.camera.height, 480);
  EXPECT_EQ(scene.render.spp, 16);
  EXPECT_EQ(scene.render.max_depth, 5);
  EXPECT_EQ(scene.lights.size(), 2u);
  EXPECT_GE(scene.world.spheres.size(), 6u);
}

TEST(ShippedScenes, ManySpheresHasAtLeastTenThousand) {
  const SceneDescription scene = parse_scene_file(test::scenes_dir() / "many_spheres.yaml");
  EXPECT_GE(scene.world.spheres.size(), 10000u);
}

TEST(ShippedScenes, MeshSceneUsesTheObjColours) {
  const SceneDescription scene = parse_scene_file(test::scenes_dir() / "mesh.yaml");
  ASSERT_EQ(scene.world.meshes.size(), 1u);
  EXPECT_EQ(scene.world.meshes[0].material, kNoMaterial);
  EXPECT_TRUE(std::filesystem::is_regular_file(scene.world.meshes[0].file));
}

TEST(ShippedScenes, InstancingNestsOneLevel) {
  const SceneDescription scene = parse_scene_file(test::scenes_dir() / "instancing.yaml");
  std::size_t instance_entries = scene.world.instances.size();
  bool nested = false;
  for (const ObjectDesc& object : scene.objects) {
    instance_entries += object.instances.size();
    nested = nested || !object.instances.empty();
  }
  EXPECT_TRUE(nested);
  EXPECT_GE(instance_entries, 20u);
  EXPECT_LE(instance_entries, 50u);
}

}  // namespace shipped_scenes_test
}  // namespace rtpro
