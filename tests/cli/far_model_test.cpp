// A glTF model placed far from the origin (a georeferenced scan, a city tile) loads wherever the
// backends can trace it (±1e16), and `rtpro info` reports where it is.
#include "scene/gltf_test_files.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace rtpro {
namespace far_model_test {

TEST(FarModel, AGltfNodeFiveBillionAwayLoadsAndInfoShowsItsBounds) {
  test::scratch_dir();
  test::GltfFile gltf;
  gltf.mesh(gltf.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3"));
  gltf.node({{"mesh", 0}, {"translation", {5e9, 0, 0}}});
  gltf.scene({0});
  const auto model = gltf.write("far");

  const std::string text = test::run_rtpro("info " + model.string(), 0);
  EXPECT_NE(text.find("bounds       [5000000000.000, 0.000, 0.000] .. [5000000000.000, 1.000, 0.000]"),
            std::string::npos)
      << text;
  const auto json = nlohmann::json::parse(test::run_rtpro("info --json " + model.string() + " 2>/dev/null", 0));
  EXPECT_EQ(json["bounds"]["lower"][0].get<double>(), 5e9);
  EXPECT_EQ(json["bounds"]["upper"][1].get<double>(), 1.0);
}

}  // namespace far_model_test
}  // namespace rtpro
