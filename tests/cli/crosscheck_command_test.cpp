// `rtpro crosscheck` reads its scene as `render` and `info` do (issue 42): the command line's scene
// overrides apply, and the up-front memory estimate is checked against the budget before the
// scene is built.
#include "test_paths.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace crosscheck_command_test {

using test::run_rtpro;

// A ground (a large sphere) under two balls, the camera looking down on them.
const char* kScene = R"(rtpro: 1
camera: {position: [0, 3, 7], look_at: [0, 0, 0], fov: 45, resolution: [32, 24]}
lights: [{type: point, position: [-3, 8, 4], intensity: 2}]
world:
  - {type: sphere, center: [0, -500, 0], radius: 500}
  - {type: sphere, center: [-1, 0.5, 0], radius: 0.5}
  - {type: sphere, center: [1, 0.8, -1], radius: 0.8}
)";

// The "top-level spheres  N closest hits" line of a passing crosscheck.
long sphere_hits(const std::string& args) {
  const std::string out = run_rtpro("crosscheck " + args + " --rays 400", 0);
  const std::string label = "top-level spheres";
  const std::size_t at = out.find(label);
  if (at == std::string::npos) {
    ADD_FAILURE() << out;
    return -1;
  }
  return std::stol(out.substr(at + label.size()));
}

TEST(CrosscheckCommand, SceneOverridesChangeTheRaysCrosschecked) {
  const std::string scene = test::write_file("scene.yaml", kScene).string();
  const long as_written = sphere_hits(scene);
  // The ground shrunk to a ball far below the camera: most rays that hit it now miss.
  const long shrunk_ground = sphere_hits(scene + " --set world.0.radius=1");
  EXPECT_GT(as_written, 0);
  EXPECT_LT(shrunk_ground, as_written / 2);
  EXPECT_EQ(sphere_hits(scene + " --set world.0.radius=500"), as_written);
}

TEST(CrosscheckCommand, ABadOverrideIsRefusedNamingItsFlag) {
  const std::string scene = test::write_file("scene.yaml", kScene).string();
  const std::string out = run_rtpro("crosscheck " + scene + " --set world.1.radius=-1", 2);
  EXPECT_NE(out.find("rtpro: error: --set world.1.radius=-1: sphere.radius must be > 0, got -1"), std::string::npos)
      << out;
  EXPECT_EQ(out.find("crosscheck native"), std::string::npos) << out;
}

TEST(CrosscheckCommand, AnEstimateOverTheMemoryCapIsRefusedBeforeTheBuild) {
  const std::string scene = test::write_file("scene.yaml", kScene).string();
  // 3000 x 3000 pixels of three floats, with one output copy: about 200 MiB.
  const std::string out = run_rtpro("crosscheck " + scene + " --set camera.resolution=[3000,3000] --max-memory 64", 2);
  EXPECT_NE(out.find("more than the memory budget of 64.0 MiB (--max-memory 64)"), std::string::npos) << out;
  EXPECT_EQ(out.find("crosscheck native"), std::string::npos) << out;
  run_rtpro("crosscheck " + scene + " --set camera.resolution=[3000,3000] --max-memory 512 --rays 100", 0);
}

}  // namespace crosscheck_command_test
}  // namespace rtpro
