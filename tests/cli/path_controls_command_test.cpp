// Cycles' Light Paths controls on the command line: the flags, `rtpro info`, the EXR metadata and
// the refusals, running the real binary.
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

namespace rtpro {
namespace path_controls_command_test {

using test::expect_rtpro_answer;
using test::render_args;
using test::run_rtpro;

const char* kPathScene = R"(rtpro: 1
camera: {position: [0, 1, -4], look_at: [0, 0.5, 0], fov: 40, resolution: [8, 6]}
render: {spp: 1, max_depth: 6, integrator: path}
materials:
  lamp: {type: diffuse, color: [0, 0, 0], emission: [10, 10, 10]}
world:
  - {type: sphere, center: [0, -1000, 0], radius: 1000}
  - {type: sphere, center: [0, 2, 0], radius: 0.3, material: lamp}
)";

// The value of the EXR header's string attribute `name` (name, NUL, "string", NUL, a 4-byte
// little-endian size, the bytes), or "(missing)".
std::string exr_string_attribute(const std::filesystem::path& file, const std::string& name) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string key = name + std::string(1, '\0') + "string" + std::string(1, '\0');
  const std::size_t at = bytes.find(key);
  if (at == std::string::npos || at + key.size() + 4 > bytes.size()) return "(missing)";
  std::uint32_t size = 0;
  std::memcpy(&size, bytes.data() + at + key.size(), 4);
  return bytes.substr(at + key.size() + 4, size);
}

TEST(PathControlsCommand, FlagsReachTheRenderInfoAndMetadata) {
  const auto scene = test::write_file("scene.yaml", kPathScene);
  const auto image = scene.parent_path() / "out.exr";
  const std::string flags =
      " --max-diffuse-depth 2 --max-glossy-depth 3 --clamp-indirect 3 --clamp-direct 20 --filter-glossy 1";
  run_rtpro(render_args(scene, image, "-q" + flags), 0);
  EXPECT_EQ(exr_string_attribute(image, "rtpro:max_depth"), "6");
  EXPECT_EQ(exr_string_attribute(image, "rtpro:max_diffuse_depth"), "2");
  EXPECT_EQ(exr_string_attribute(image, "rtpro:max_glossy_depth"), "3");
  EXPECT_EQ(exr_string_attribute(image, "rtpro:max_transmission_depth"), "6");
  EXPECT_EQ(exr_string_attribute(image, "rtpro:clamp_direct"), "20");
  EXPECT_EQ(exr_string_attribute(image, "rtpro:clamp_indirect"), "3");
  EXPECT_EQ(exr_string_attribute(image, "rtpro:filter_glossy"), "1");

  // `rtpro info` takes scene values through --set, as the file gives them.
  const std::string sets =
      " --set render.max_diffuse_depth=2 --set render.max_glossy_depth=3 --set render.clamp_indirect=3"
      " --set render.clamp_direct=20 --set render.filter_glossy=1";
  const std::string out = run_rtpro("info " + scene.string() + " --json" + sets + " 2>/dev/null", 0);
  const nlohmann::json render = nlohmann::json::parse(out)["render"];
  EXPECT_EQ(render["max_diffuse_depth"].get<int>(), 2);
  EXPECT_EQ(render["max_transmission_depth"].get<int>(), 6);
  EXPECT_EQ(render["clamp_indirect"].get<double>(), 3.0);
  EXPECT_EQ(render["filter_glossy"].get<double>(), 1.0);
  expect_rtpro_answer("info " + scene.string() + sets, 0,
                      "diffuse/glossy/transmission depth 2/3/6, clamp direct 20, clamp indirect 3, filter glossy 1");
}

TEST(PathControlsCommand, BadValuesAreRefusedWithTheirFlagOrPlace) {
  const auto scene = test::write_file("scene.yaml", kPathScene);
  const auto image = scene.parent_path() / "out.exr";
  expect_rtpro_answer(render_args(scene, image, "--max-diffuse-depth 0"), 2, "--max-diffuse-depth 0");
  expect_rtpro_answer(render_args(scene, image, "--max-transmission-depth 1025"), 2, "from 1 to 1024");
  expect_rtpro_answer(render_args(scene, image, "--clamp-indirect -1"), 2, "--clamp-indirect -1");
  expect_rtpro_answer(render_args(scene, image, "--filter-glossy x"), 2, "--filter-glossy x");
  expect_rtpro_answer(render_args(scene, image, "--max-depth 1025"), 2, "from 0 to 1024");
  const auto too_deep = test::write_file("too_deep.yaml", R"(rtpro: 1
camera: {position: [0, 1, -4], look_at: [0, 0.5, 0], resolution: [8, 6]}
render: {integrator: path, max_depth: 1025}
)");
  expect_rtpro_answer("info " + too_deep.string(), 2, "too_deep.yaml:3:39: render.max_depth must be from 0 to 1024");
  EXPECT_FALSE(std::filesystem::exists(image));
}

}  // namespace path_controls_command_test
}  // namespace rtpro
