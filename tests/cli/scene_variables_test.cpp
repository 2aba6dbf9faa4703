// Scene variables (-D NAME=VALUE, `variables:`, $name) and includes, through the real binary.
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace rtpro {
namespace scene_variables_test {

using test::expect_rtpro_answer;
using test::run_rtpro;

nlohmann::json info(const std::string& args) { return nlohmann::json::parse(run_rtpro("info --json " + args, 0)); }

const char* kCamera = "camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 40, resolution: [16, 12]}\n";

TEST(SceneVariables, DefaultsAreReplacedByDefines) {
  const auto scene = test::write_file("v.yaml", std::string("rtpro: 1\n") + kCamera +
                                                    "variables: {spp: 4, seed: 7}\n"
                                                    // ${...} in block style: '{' cannot start
                                                    // a plain scalar inside [...] or {...}
                                                    "render:\n  spp: $spp\n  seed: ${seed}\n");
  EXPECT_EQ(info(scene.string())["render"]["spp"], 4) << info(scene.string()).dump();
  EXPECT_EQ(info(scene.string() + " -D spp=9")["render"]["spp"], 9);
  EXPECT_EQ(info(scene.string() + " --define seed=11")["render"]["seed"], 11);
}

TEST(SceneVariables, ListsAndTextSubstitute) {
  const auto dir = test::scratch_dir();
  const auto scene =
      test::write_file("v.yaml", std::string("rtpro: 1\n") +
                                     "camera: {position: $eye, look_at: [0, 0, 0], fov: 40, resolution: [16, 12]}\n"
                                     "variables: {eye: [0, 0, 5]}\n"
                                     "world: [{type: sphere, center: [0, 0, 0], radius: 1}]\n");
  const nlohmann::json json = info(scene.string() + " -D eye=[0,2,9]");
  EXPECT_EQ(json["camera"]["position"], nlohmann::json::array({0, 2, 9})) << json.dump();
}

TEST(SceneVariables, MistakesAreErrorsAtTheirPlace) {
  const auto scene = test::write_file("v.yaml", std::string("rtpro: 1\n") + kCamera +
                                                    "variables: {radius: 1}\n"
                                                    "world: [{type: sphere, center: [0, 0, 0], radius: $raduis}]\n");
  std::string out = expect_rtpro_answer("info " + scene.string(), 2, "v.yaml:4:");
  EXPECT_NE(out.find("undefined variable '$raduis'; did you mean '$radius'?"), std::string::npos) << out;
  const auto good = test::write_file("g.yaml", std::string("rtpro: 1\n") + kCamera +
                                                   "variables: {radius: 1}\n"
                                                   "world: [{type: sphere, center: [0, 0, 0], radius: $radius}]\n");
  out = run_rtpro("info " + good.string() + " -D radiu=2", 2);
  EXPECT_NE(out.find("-D radiu=2: the scene uses no variable '$radiu'; did you mean 'radius'?"), std::string::npos)
      << out;
  expect_rtpro_answer("info " + good.string() + " -D radius=big", 2, "-D radius=big: sphere.radius: expected a number");
  expect_rtpro_answer("info " + good.string() + " -D 2x=1", 2, "-D 2x=1: variables: '2x' is not a name");
}

TEST(SceneIncludes, MergeMappingsAndSpliceLists) {
  const auto dir = test::scratch_dir();
  std::filesystem::create_directories(dir / "parts");
  test::write_file("parts/base.yaml", std::string(kCamera) + "render: {spp: 16, seed: 5}\n");
  test::write_file("parts/spheres.yaml",
                   "- {type: sphere, center: [2, 0, 0], radius: 0.5}\n"
                   "- {type: sphere, center: [-2, 0, 0], radius: 0.5}\n");
  const auto scene = test::write_file("scene.yaml",
                                      "rtpro: 1\ninclude: parts/base.yaml\nrender: {spp: 4}\n"
                                      "world:\n  - {type: sphere, center: [0, 0, 0], radius: 1}\n"
                                      "  - {include: parts/spheres.yaml}\n");
  const nlohmann::json json = info(scene.string());
  EXPECT_EQ(json["render"]["spp"], 4) << json.dump();  // the including file's own key wins
  EXPECT_EQ(json["render"]["seed"], 0);                // ... as a whole value: no deep merge
  EXPECT_EQ(json["spheres"]["stored"], 3) << json.dump();
}

TEST(SceneIncludes, MeshPathsAreRelativeToTheFileThatWritesThem) {
  const auto dir = test::scratch_dir();
  test::write_file("props/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  test::write_file("props/table.yaml", "- {type: mesh, file: tri.obj}\n");
  const auto scene =
      test::write_file("scene.yaml", std::string("rtpro: 1\n") + kCamera + "world: [{include: props/table.yaml}]\n");
  const nlohmann::json json = info(scene.string());
  EXPECT_EQ(json["triangles"]["stored"], 1) << json.dump();
}

TEST(SceneIncludes, CyclesMissingFilesAndErrorsNameTheFile) {
  const auto dir = test::scratch_dir();
  test::write_file("a.yaml", std::string("rtpro: 1\n") + kCamera + "world: [{include: b.yaml}]\n");
  test::write_file("b.yaml", "- {include: a.yaml}\n");
  expect_rtpro_answer("info " + (dir / "a.yaml").string(), 2, "b.yaml:1:13: include cycle: a.yaml -> b.yaml -> a.yaml");

  test::write_file("c.yaml", std::string("rtpro: 1\n") + kCamera + "world: [{include: missing.yaml}]\n");
  expect_rtpro_answer("info " + (dir / "c.yaml").string(), 2, "c.yaml:3:19: cannot include 'missing.yaml'");

  test::write_file("bad.yaml", "- {type: sphere, center: [0, 0, 0], radius: -1}\n");
  test::write_file("d.yaml", std::string("rtpro: 1\n") + kCamera + "world: [{include: bad.yaml}]\n");
  expect_rtpro_answer("info " + (dir / "d.yaml").string(), 2, "bad.yaml:1:");

  test::write_file("self.yaml", "include: self.yaml\n");
  expect_rtpro_answer("info " + (dir / "self.yaml").string(), 2, "include cycle: self.yaml -> self.yaml");
}

TEST(SceneIncludes, DepthIsLimited) {
  const auto dir = test::scratch_dir();
  for (int i = 0; i < 20; ++i)
    test::write_file("d" + std::to_string(i) + ".yaml", "include: d" + std::to_string(i + 1) + ".yaml\n");
  test::write_file("d20.yaml", std::string("rtpro: 1\n") + kCamera);
  expect_rtpro_answer("info " + (dir / "d0.yaml").string(), 2, "includes nested deeper than 16 files");
}

}  // namespace scene_variables_test
}  // namespace rtpro
