// The scene file's side of motion blur: camera.shutter, and keyframed transforms and sphere
// centres read at the shutter's time steps (scene/motion.h).
#include "rtpro/core/error.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace yaml_motion_test {

SceneDescription parse(const std::string& shutter, const std::string& world, const std::string& defines = "") {
  std::vector<std::string> overrides;
  if (!defines.empty()) overrides.push_back("variables.frame=" + defines);
  return parse_scene_text("rtpro: 1\ncamera: {position: [0, 0, -5], look_at: [0, 0, 0], shutter: " + shutter +
                              "}\nobjects:\n  ball: [{type: sphere}]\nworld:\n" + world,
                          "motion.yaml", overrides);
}

const std::string kMovingInstance =
    "  - {type: instance, object: ball, transform: {translate: {keyframes: {1: [0, 0, 0], 3: [4, 0, 0]}}}}\n";

TEST(YamlMotion, KeyframedTranslationGivesTwoStepsOverTheShutter) {
  const SceneDescription scene = parse("[-0.5, 0.5]", kMovingInstance, "2");
  EXPECT_EQ(scene.camera.shutter, (Shutter{-0.5f, 0.5f}));
  const InstanceDesc& instance = scene.world.instances.at(0);
  EXPECT_FLOAT_EQ(instance.transform.m[0][3], 2.0f);                // frame 2
  ASSERT_EQ(instance.transform_steps.size(), 2u);                   // linear in time: no more are needed
  EXPECT_FLOAT_EQ(instance.transform_steps.front().m[0][3], 1.0f);  // frame 1.5
  EXPECT_FLOAT_EQ(instance.transform_steps.back().m[0][3], 3.0f);   // frame 2.5
}

TEST(YamlMotion, ClosedShutterOrStillValuesKeepNoSteps) {
  EXPECT_TRUE(parse("[0, 0]", kMovingInstance).world.instances.at(0).transform_steps.empty());
  EXPECT_TRUE(parse("[0, 1]", "  - {type: instance, object: ball, transform: {translate: [1, 2, 3]}}\n")
                  .world.instances.at(0)
                  .transform_steps.empty());
  // Before the first key the value holds still.
  EXPECT_TRUE(parse("[0, 1]",
                    "  - {type: instance, object: ball, transform: {translate: {keyframes: {5: [0, 0, "
                    "0], 6: [1, 0, 0]}}}}\n")
                  .world.instances.at(0)
                  .transform_steps.empty());
}

TEST(YamlMotion, KeyframedRotationTakesStepsAlongTheArc) {
  const SceneDescription scene =
      parse("[0, 1]",
            "  - {type: instance, object: ball, transform: {rotate: {axis: [0, 0, 1], angle: {keyframes: {1: 0, "
            "2: 90}}}}}\n");
  const std::vector<Affine>& steps = scene.world.instances.at(0).transform_steps;
  ASSERT_GE(steps.size(), 17u);
  // The middle step is the 45° turn itself, not the chord between the ends.
  const Affine& middle = steps[steps.size() / 2];
  EXPECT_NEAR(middle.m[0][0], std::sqrt(0.5f), 1e-5f);
  EXPECT_NEAR(middle.m[1][0], std::sqrt(0.5f), 1e-5f);
}

TEST(YamlMotion, KeyframedSphereCentreMoves) {
  const SceneDescription scene =
      parse("[0, 1]", "  - {type: sphere, center: {keyframes: {1: [0, 0, 0], 2: [0, 2, 0]}}, radius: 0.5}\n");
  const SphereDesc& sphere = scene.world.spheres.at(0);
  ASSERT_EQ(sphere.center_steps.size(), 2u);
  EXPECT_FLOAT_EQ(sphere.center_steps.back().y, 2.0f);
}

TEST(YamlMotion, ShutterClosingBeforeItOpensIsRefusedAtItsLine) {
  try {
    parse("[0.5, -0.5]", kMovingInstance);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(e.message().find("camera.shutter"), std::string::npos) << e.message();
  }
}

TEST(YamlMotion, ShutterOpeningShapesTheExposure) {
  EXPECT_TRUE(parse("[-0.5, 0.5]", kMovingInstance).camera.shutter.is_box());  // the default
  const SceneDescription scene = parse_scene_text(
      "rtpro: 1\ncamera: {position: [0, 0, -5], look_at: [0, 0, 0], shutter: [0, 1], shutter_opening: [0.25, "
      "0.75]}\n",
      "motion.yaml", {});
  EXPECT_EQ(scene.camera.shutter.opening, 0.25f);
  EXPECT_EQ(scene.camera.shutter.closing, 0.75f);
  for (const char* bad : {"[0.75, 0.25]", "[-0.1, 0.5]", "[0.5, 1.5]", "[0.5]"}) {
    try {
      parse_scene_text(
          std::string("rtpro: 1\ncamera: {position: [0, 0, -5], look_at: [0, 0, 0],\n  shutter_opening: ") + bad +
              "}\n",
          "motion.yaml", {});
      FAIL() << bad << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, 3) << bad;
      EXPECT_NE(e.message().find("camera.shutter_opening"), std::string::npos) << e.message();
    }
  }
}

}  // namespace yaml_motion_test
}  // namespace rtpro
