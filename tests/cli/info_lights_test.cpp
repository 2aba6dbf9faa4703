// `rtpro info` lists every light with the intensity it is rendered with, and a glTF light with the
// photometric value its file gave (KHR_lights_punctual candela and lux at 683 lm/W), in text and
// in JSON.
#include "scene/gltf_test_files.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace rtpro {
namespace info_lights_test {

TEST(InfoLights, AGltfLightShowsItsConvertedIntensity) {
  test::scratch_dir();
  test::GltfFile gltf;
  gltf.mesh(gltf.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3"));
  gltf.json["extensions"]["KHR_lights_punctual"]["lights"] = nlohmann::json::array();
  gltf.json["extensions"]["KHR_lights_punctual"]["lights"].push_back(
      {{"type", "point"}, {"intensity", 1366.0}, {"color", {1.0, 0.5, 0.25}}});
  gltf.json["extensions"]["KHR_lights_punctual"]["lights"].push_back({{"type", "directional"}, {"intensity", 68.3}});
  gltf.node({{"mesh", 0}});
  gltf.node({{"translation", {0, 2, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  gltf.node({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  gltf.scene({0, 1, 2});
  const auto model = gltf.write("lit");

  const std::string text = test::run_rtpro("info " + model.string(), 0);
  EXPECT_NE(text.find("point: intensity 2 x colour [1, 0.5, 0.25] = [2, 1, 0.5] W/sr (radiant intensity), from "
                      "nodes[1] (extensions.KHR_lights_punctual.lights[0]): 1366 cd / 683 lm/W"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("directional: intensity 0.1 x colour [1, 1, 1] = [0.1, 0.1, 0.1] W/m^2 (irradiance), from "
                      "nodes[2] (extensions.KHR_lights_punctual.lights[1]): 68.3 lx / 683 lm/W"),
            std::string::npos)
      << text;

  const auto json = nlohmann::json::parse(test::run_rtpro("info --json " + model.string() + " 2>/dev/null", 0));
  ASSERT_EQ(json["light_list"].size(), 2u);
  EXPECT_EQ(json["light_list"][0]["type"], "point");
  EXPECT_FLOAT_EQ(json["light_list"][0]["intensity"].get<float>(), 2.0f);
  EXPECT_FLOAT_EQ(json["light_list"][0]["rendered"][2].get<float>(), 0.5f);
  EXPECT_NE(json["light_list"][0]["source"].get<std::string>().find("1366 cd"), std::string::npos);
  // What an override changes is what is rendered, and no longer the file's value.
  const auto changed = nlohmann::json::parse(
      test::run_rtpro("info --json " + model.string() + " --set lights.0.intensity=3 2>/dev/null", 0));
  EXPECT_FLOAT_EQ(changed["light_list"][0]["intensity"].get<float>(), 3.0f);
  EXPECT_FALSE(changed["light_list"][0].contains("source"));
}

}  // namespace info_lights_test
}  // namespace rtpro
