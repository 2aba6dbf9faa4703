// The scene file's `lights:` (yaml_lights.cpp), spot lights above all: their defaults, the axis
// given by direction or by look_at, and each mistake refused where it was made.
#include "rtpro/core/error.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "scene_text_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

namespace rtpro {
namespace yaml_lights_test {

using test::kHeader;

// kHeader is two lines: the light is on line 3.
std::string with_light(const std::string& light) { return kHeader + "lights:\n  - " + light + "\n"; }

SpotLightDesc spot_of(const std::string& light) {
  const SceneDescription scene = parse_scene_text(with_light(light), "test.yaml");
  EXPECT_EQ(scene.lights.size(), 1u);
  return std::get<SpotLightDesc>(scene.lights.at(0));
}

// The error the light's text gets: on line 4 at the first `token` of it, saying each fragment.
void expect_error_at(const std::string& light, const std::string& token, const std::vector<std::string>& fragments) {
  SCOPED_TRACE(light);
  const std::size_t column = light.find(token);
  ASSERT_NE(column, std::string::npos) << "'" << token << "' is not in the light";
  try {
    parse_scene_text(with_light(light), "test.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, "test.yaml");
    EXPECT_EQ(error.where().line, 4) << error.what();
    EXPECT_EQ(error.where().column, static_cast<int>(column) + 5) << error.what();  // after "  - "
    for (const std::string& fragment : fragments)
      EXPECT_NE(error.message().find(fragment), std::string::npos) << "'" << fragment << "' not in: " << error.what();
  }
}

TEST(YamlLights, ASpotLightHasDefaultsForEverythingButPositionAndAxis) {
  const SpotLightDesc spot = spot_of("{type: spot, position: [1, 3, 2], direction: [0, -2, 0]}");
  EXPECT_EQ(spot.position, Vec3(1, 3, 2));
  EXPECT_EQ(spot.direction, Vec3(0, -1, 0));  // made unit
  EXPECT_EQ(spot.color, Color(1.0f));
  EXPECT_EQ(spot.intensity, 1.0f);
  EXPECT_EQ(spot.inner_angle, 0.0f);
  EXPECT_EQ(spot.outer_angle, 45.0f);
}

TEST(YamlLights, ASpotLightReadsEveryKey) {
  const SpotLightDesc spot = spot_of(
      "{type: spot, position: [0, 4, 0], direction: [3, 0, 4], color: [1, 0.5, 0.25], intensity: 7, "
      "inner_angle: 15, outer_angle: 90}");
  EXPECT_NEAR(spot.direction.x, 0.6f, 1e-7f);
  EXPECT_EQ(spot.direction.y, 0.0f);
  EXPECT_NEAR(spot.direction.z, 0.8f, 1e-7f);
  EXPECT_EQ(spot.color, Color(1.0f, 0.5f, 0.25f));
  EXPECT_EQ(spot.intensity, 7.0f);
  EXPECT_EQ(spot.inner_angle, 15.0f);
  EXPECT_EQ(spot.outer_angle, 90.0f);
  // Equal angles are a hard edge.
  EXPECT_EQ(
      spot_of("{type: spot, position: [0, 1, 0], direction: [0, -1, 0], inner_angle: 30, outer_angle: 30}").inner_angle,
      30.0f);
}

TEST(YamlLights, ASpotLightsAxisCanBeAPointItLooksAt) {
  const SpotLightDesc spot = spot_of("{type: spot, position: [1, 5, 3], look_at: [1, 1, 0]}");
  EXPECT_NEAR(spot.direction.x, 0.0f, 1e-7f);
  EXPECT_NEAR(spot.direction.y, -0.8f, 1e-6f);
  EXPECT_NEAR(spot.direction.z, -0.6f, 1e-6f);
}

TEST(YamlLights, ASpotLightBecomesARenderLightWithItsConesCosines) {
  const RenderScene scene = build_render_scene(parse_scene_text(
      with_light("{type: spot, position: [0, 2, 0], look_at: [0, 0, 0], color: [1, 0.5, 1], intensity: 4, "
                 "inner_angle: 20, outer_angle: 60}"),
      "test.yaml"));
  ASSERT_EQ(scene.lights.size(), 1u);
  const auto& spot = std::get<SpotLight>(scene.lights[0]);
  EXPECT_EQ(spot.position, Vec3(0, 2, 0));
  EXPECT_EQ(spot.axis, Vec3(0, -1, 0));
  EXPECT_EQ(spot.radiance, Color(4.0f, 2.0f, 4.0f));
  EXPECT_NEAR(spot.cos_inner, std::cos(20.0 * std::numbers::pi / 180.0), 1e-7);
  EXPECT_NEAR(spot.cos_outer, 0.5, 1e-7);
}

TEST(YamlLights, ASpotLightNeedsExactlyOneAxis) {
  expect_error_at("{type: spot, position: [0, 1, 0]}", "{", {"spot light needs 'direction'", "or 'look_at'"});
  expect_error_at("{type: spot, position: [0, 1, 0], direction: [0, -1, 0], look_at: [0, 0, 0]}", "[0, 0, 0]",
                  {"spot light.look_at", "direction or by look_at, not both"});
  expect_error_at("{type: spot, position: [0, 1, 0], direction: [0, 0, 0]}", "[0, 0, 0]",
                  {"spot light.direction must not be zero-length"});
  expect_error_at("{type: spot, position: [2, 1, 0], look_at: [2, 1, 0.0]}", "[2, 1, 0.0]",
                  {"spot light.look_at must differ from position"});
  expect_error_at("{type: spot, direction: [0, -1, 0]}", "{", {"missing the required key 'position'"});
}

TEST(YamlLights, ASpotLightsAnglesAreRefusedOutsideTheirRange) {
  const std::string spot = "{type: spot, position: [0, 1, 0], direction: [0, -1, 0], ";
  expect_error_at(spot + "outer_angle: 0}", "0}", {"spot light.outer_angle must be > 0"});
  expect_error_at(spot + "outer_angle: 90.5}", "90.5", {"spot light.outer_angle", "from 0 to 90 degrees, got 90.5"});
  expect_error_at(spot + "outer_angle: -10}", "-10", {"spot light.outer_angle", "from 0 to 90 degrees"});
  expect_error_at(spot + "inner_angle: -1}", "-1}", {"spot light.inner_angle", "from 0 to 90 degrees, got -1"});
  expect_error_at(spot + "inner_angle: 50, outer_angle: 40}", "50",
                  {"spot light.inner_angle (50) must not exceed outer_angle (40)"});
  expect_error_at(spot + "inner_angle: 46}", "46", {"must not exceed outer_angle (45, the default)"});
  expect_error_at(spot + "outer_angle: wide}", "wide", {"spot light.outer_angle: expected a number"});
  expect_error_at(spot + "intensity: -3}", "-3", {"spot light.intensity must be >= 0"});
  expect_error_at(spot + "color: [1, -0.5, 1]}", "-0.5", {"spot light.color"});
  expect_error_at(spot + "angle: 30}", "angle", {"unknown key 'angle' in spot light"});
}

TEST(YamlLights, UnknownLightTypesSuggestTheClosest) {
  expect_error_at("{type: spto, position: [0, 1, 0]}", "spto", {"unknown light type 'spto'", "did you mean 'spot'?"});
}

TEST(YamlLights, EveryKindIsReadInOrder) {
  const SceneDescription scene = parse_scene_text(kHeader + R"(lights:
  - {type: point, position: [0, 1, 0]}
  - {type: spot, position: [0, 1, 0], direction: [0, -1, 0]}
  - {type: directional, direction: [0, -1, 0]}
  - {type: sphere, center: [0, 3, 0], radius: 0.5, samples: 2}
  - {type: quad, position: [0, 4, 0], edge1: [1, 0, 0], edge2: [0, 0, 1]}
)",
                                                  "test.yaml");
  ASSERT_EQ(scene.lights.size(), 5u);
  EXPECT_TRUE(std::holds_alternative<PointLightDesc>(scene.lights[0]));
  EXPECT_TRUE(std::holds_alternative<SpotLightDesc>(scene.lights[1]));
  EXPECT_TRUE(std::holds_alternative<DirectionalLightDesc>(scene.lights[2]));
  EXPECT_EQ(std::get<SphereLightDesc>(scene.lights[3]).samples, 2);
  EXPECT_TRUE(std::holds_alternative<QuadLightDesc>(scene.lights[4]));
}

}  // namespace yaml_lights_test
}  // namespace rtpro
