// The scene file's `environment:`: what it reads, and each mistake refused where it was made.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include "test_paths.h"
#include "scene_text_error.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace yaml_environment_test {

using test::kHeader;
using test::parse_error;

std::string sunset() { return (test::scenes_dir() / "environments" / "sunset.exr").string(); }

// The error is on line 3 (the environment's) and says each fragment.
void expect_error_on_line_3(const std::string& environment, const std::vector<std::string>& fragments) {
  const InputError error = parse_error(kHeader + environment + "\n");
  EXPECT_EQ(error.where().file, "test.yaml") << error.what();
  EXPECT_EQ(error.where().line, 3) << error.what();
  EXPECT_GT(error.where().column, 1) << error.what();
  for (const std::string& fragment : fragments)
    EXPECT_NE(error.message().find(fragment), std::string::npos) << "'" << fragment << "' not in: " << error.what();
}

TEST(YamlEnvironment, AbsentMeansNone) {
  EXPECT_FALSE(parse_scene_text(kHeader, "test.yaml").environment);
  EXPECT_FALSE(build_render_scene(parse_scene_text(kHeader, "test.yaml")).environment);
}

TEST(YamlEnvironment, ReadsAnImageWithItsSettings) {
  const SceneDescription d =
      parse_scene_text(kHeader + "environment: {file: " + sunset() +
                           ", color: [1, 0.5, 0.25], intensity: 2, rotation: [0, 90, 0], visible: false}\n",
                       "test.yaml");
  ASSERT_TRUE(d.environment);
  EXPECT_EQ(d.environment->file, sunset());
  EXPECT_EQ(d.environment->file_where.line, 3);
  EXPECT_FALSE(d.environment->visible);
  const Vec3 x = d.environment->rotation.apply_vector(Vec3(1, 0, 0));
  EXPECT_NEAR(x.z, -1.0f, 1e-6f);  // 90° about +Y takes +X to −Z
  const RenderScene scene = build_render_scene(d);
  ASSERT_TRUE(scene.environment);
  EXPECT_EQ(scene.environment->scale, Color(2.0f, 1.0f, 0.5f));
  EXPECT_FALSE(scene.environment->visible);
}

TEST(YamlEnvironment, AColourAloneIsAConstantEnvironment) {
  const RenderScene scene =
      build_render_scene(parse_scene_text(kHeader + "environment: {color: [0.2, 0.3, 0.4]}\n", "test.yaml"));
  ASSERT_TRUE(scene.environment);
  EXPECT_TRUE(scene.environment->file.empty());
  EXPECT_EQ(scene.environment->scale, Color(0.2f, 0.3f, 0.4f));
  EXPECT_TRUE(scene.environment->visible);
}

TEST(YamlEnvironment, RefusesMistakesWhereTheyAreMade) {
  expect_error_on_line_3("environment: {file: no_such_sky.exr}", {"environment.file", "no_such_sky.exr", "not found"});
  expect_error_on_line_3("environment: {file: " + (test::scenes_dir() / "textures" / "uv_grid.png").string() + "}",
                         {"not a scene-linear image", "EXR"});
  expect_error_on_line_3("environment: {file: ''}", {"environment.file"});
  expect_error_on_line_3("environment: {intensity: -1}", {"environment.intensity", "0 or more"});
  expect_error_on_line_3("environment: {visible: maybe}", {"environment.visible must be true or false", "maybe"});
  expect_error_on_line_3("environment: {colour: [1, 1, 1]}", {"unknown key 'colour'", "did you mean 'color'?"});
  expect_error_on_line_3("environment: {rotation: [0, 90]}", {"environment.rotation"});
  expect_error_on_line_3("environment: {color: [1, -1, 1]}", {"environment.color"});
  expect_error_on_line_3("environment: [1, 2]", {"environment"});
}

}  // namespace yaml_environment_test
}  // namespace rtpro
