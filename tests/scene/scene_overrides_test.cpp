// Command-line overrides (--set key=value) of a scene text, applied before validation.
#include "rtpro/scene/scene_parser.h"
#include "scene_text_error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro::test {
namespace scene_overrides_test {

TEST(SceneParserOverrides, SetValuesBeforeValidation) {
  const std::string text = kHeader + "render: {spp: 4}\nlights: [{type: point, position: [0, 1, 0]}]\n";
  const SceneDescription scene = parse_scene_text(
      text, "test.yaml",
      {"render.spp=64", "camera.resolution=[320, 240]", "camera.fov=30", "render.seed=7", "lights.0.intensity=2"});
  EXPECT_EQ(scene.render.spp, 64);
  EXPECT_EQ(scene.render.seed, 7u);
  EXPECT_EQ(scene.camera.width, 320);
  EXPECT_EQ(scene.camera.height, 240);
  EXPECT_EQ(scene.camera.fov_degrees, 30.0f);
  EXPECT_EQ(std::get<PointLightDesc>(scene.lights.at(0)).intensity, 2.0f);
}

TEST(SceneParserOverrides, CreateMissingSections) {
  const SceneDescription scene =
      parse_scene_text(kHeader, "test.yaml", {"render.max_depth=2", "materials.red.color=[1,0,0]"});
  EXPECT_EQ(scene.render.max_depth, 2);
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_EQ(scene.materials[1].color, Color(1, 0, 0));
}

TEST(SceneParserOverrides, ChangeOnlyTheAliasTheyName) {
  const std::string text = kHeader + "materials:\n  a: &m {color: [0, 0, 1]}\n  b: *m\n";
  const SceneDescription scene = parse_scene_text(text, "test.yaml", {"materials.b.color=[1, 1, 1]"});
  EXPECT_EQ(scene.materials.at(1).color, Color(0, 0, 1));
  EXPECT_EQ(scene.materials.at(2).color, Color(1, 1, 1));
}

void check_override_error(const std::string& override_text, const std::vector<std::string>& fragments) {
  const InputError error = parse_error(kHeader + "render: {spp: 4}\n", {override_text});
  EXPECT_EQ(error.where().file, "--set " + override_text);
  EXPECT_EQ(error.where().line, 0);
  EXPECT_EQ(std::string(error.what()).rfind("--set " + override_text + ": ", 0), 0u) << error.what();
  for (const std::string& fragment : fragments)
    EXPECT_NE(error.message().find(fragment), std::string::npos) << "'" << fragment << "' not in: " << error.what();
}

TEST(SceneParserOverrides, ErrorsNameTheOverride) {
  check_override_error("render.spp=abc", {"render.spp: expected an integer, got 'abc'"});
  check_override_error("render.spp=0", {"render.spp", "from 1 to 65536"});
  check_override_error("camera.resolution=[320]", {"camera.resolution", "a list of 1 item"});
  check_override_error("camera.fov=.inf", {"camera.fov", "finite"});
  check_override_error("render.sp=64", {"unknown key 'sp' in render; did you mean 'spp'?"});
  check_override_error("rendr.spp=64", {"unknown key 'rendr'", "did you mean 'render'?"});
  check_override_error("render.spp", {"expected key=value"});
  check_override_error("render..spp=4", {"empty key name"});
  check_override_error("render.spp.x=4", {"'spp' is a single value"});
  check_override_error("lights.0.intensity=1", {"lights: expected a list of lights, got a mapping"});
  check_override_error("camera.resolution=[1, 2", {"YAML syntax error"});
  check_override_error("materials.\"Material.001.color=[1,0,0]", {"a quoted key name has no closing \""});
  check_override_error("materials.'a'b.color=[1,0,0]", {"expected key=value", "quoted"});
}

// Blender names materials "Material.001": a dot inside a name made the name unreachable. Quoted,
// in either quotes, a name is one key, dots and '=' included.
TEST(SceneParserOverrides, QuotedNamesKeepTheirDots) {
  const std::string text = kHeader + "materials:\n  Material.001: {color: [0, 0, 1]}\n  a=b: {color: [0, 0, 1]}\n";
  const SceneDescription scene = parse_scene_text(
      text, "test.yaml", {"materials.\"Material.001\".color=[1, 0, 0]", "materials.'a=b'.color=[0, 1, 0]"});
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.materials.at(1).name, "Material.001");
  EXPECT_EQ(scene.materials.at(1).color, Color(1, 0, 0));
  EXPECT_EQ(scene.materials.at(2).color, Color(0, 1, 0));
}

}  // namespace scene_overrides_test
}  // namespace rtpro::test
