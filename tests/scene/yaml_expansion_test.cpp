// Variables, keyframes and includes at the YAML document level, through parse_scene_text.
#include "rtpro/core/error.h"
#include "rtpro/scene/scene_parser.h"
#include "test_paths.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace yaml_expansion_test {

const std::string kScene = "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 40, resolution: [8, 8]}\n";

SceneDescription parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  // Beside the files a test writes (scratch_dir() would empty the folder).
  return parse_scene_text(text, test::write_file(".keep", "").parent_path() / "scene.yaml", overrides);
}

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse(text, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(YamlVariables, WholeValuesTextAndEscapes) {
  const SceneDescription scene = parse(kScene +
                                       "variables: {shine: 20, name: chrome, red: [0.9, 0.1, 0.1]}\n"
                                       "materials:\n"
                                       "  ${name}_ball: {color: $red, shininess: $shine}\n"
                                       "  \"cost$$\": {color: [0.5, 0.5, 0.5]}\n");
  ASSERT_EQ(scene.materials.size(), 3u);               // the default material, then the two
  EXPECT_EQ(scene.materials[1].name, "${name}_ball");  // keys are names, never substituted
  EXPECT_EQ(std::get<PhongParams>(scene.materials[1].params).shininess, 20.0f);
  EXPECT_EQ(scene.materials[1].color.x, 0.9f);
}

TEST(YamlVariables, OverridesReplaceDefaultsAndMistakesNameTheirPlace) {
  const std::string text = kScene + "variables: {spp: 4}\nrender: {spp: $spp}\n";
  EXPECT_EQ(parse(text).render.spp, 4);
  EXPECT_EQ(parse(text, {"variables.spp=9"}).render.spp, 9);
  EXPECT_NE(error_of(kScene + "render: {spp: $nope}\n").find("scene.yaml:3:15: undefined variable '$nope'"),
            std::string::npos);
  EXPECT_NE(error_of(kScene + "render: {spp: a$}\n").find("'$' must start a variable reference"), std::string::npos);
  EXPECT_NE(error_of(kScene + "variables: [1]\n").find("variables: expected a mapping"), std::string::npos);
}

// FORMAT.md: the variable `frame` is 1 when unset; `$frame` was "undefined variable" instead.
TEST(YamlVariables, FrameIsOneWhenNothingSetsIt) {
  const SceneDescription scene = parse(kScene + "render:\n  spp: $frame\n  seed: ${frame}0\n");
  EXPECT_EQ(scene.render.spp, 1);
  EXPECT_EQ(scene.render.seed, 10u);
  EXPECT_EQ(parse(kScene + "render: {spp: $frame}\n", {"variables.frame=7"}).render.spp, 7);
}

TEST(YamlKeyframes, StepHoldsTheLastKeyAtOrBeforeTheFrame) {
  const std::string text = kScene + "render: {spp: {keyframes: {1: 4, 10: 16}, interpolation: step}}\n";
  EXPECT_EQ(parse(text, {"variables.frame=9"}).render.spp, 4);
  EXPECT_EQ(parse(text, {"variables.frame=10"}).render.spp, 16);
  EXPECT_NE(error_of(text, {"variables.frame=soon"}).find("frame: expected a frame number"), std::string::npos);
  EXPECT_NE(error_of(kScene + "render: {spp: {keyframes: {one: 4}}}\n").find("a frame number"), std::string::npos);
  EXPECT_NE(error_of(kScene + "render: {spp: {keyframes: {1: 4}, ease: in}}\n").find("unknown key 'ease'"),
            std::string::npos);
}

TEST(YamlIncludes, IncludedErrorsNameTheIncludedFile) {
  test::write_file("materials.yaml", "materials:\n  red: {color: [1, 0, 0], shininess: -3}\n");
  const std::string message = error_of(kScene + "include: materials.yaml\n");
  EXPECT_NE(message.find("materials.yaml:2:"), std::string::npos) << message;
  test::write_file("list.yaml", "- 1\n");
  EXPECT_NE(error_of(kScene + "include: list.yaml\n").find("a mapping includes a mapping, got a list of 1 item"),
            std::string::npos);
}

}  // namespace yaml_expansion_test
}  // namespace rtpro
