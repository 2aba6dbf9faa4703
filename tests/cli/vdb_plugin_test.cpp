// The rtpro executable loads OpenVDB (through librtpro_vdb.so) only for a scene that names a .vdb
// file: see src/volume/vdb_plugin_api.h.
#include "rtpro/volume/vdb_file.h"
#include "sphere_on_floor.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace rtpro {
namespace vdb_plugin_test {

using test::render_args;
using test::rtpro_executable;
using test::run_command;

const std::string kTinyScene = test::sphere_on_floor_scene();

// A scene with a small grid volume beside the sphere, its .vdb file written beside it in `folder`
// (the test's scratch folder, where write_file writes).
std::filesystem::path scene_with_volume(const std::filesystem::path& folder) {
  VdbGridSpec grid;
  grid.name = "density";
  grid.voxel_size = 0.25;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y)
      for (int z = 0; z < 4; ++z) grid.voxels.push_back({{x, y, z}, 0.5f});
  write_vdb_file(folder / "cube.vdb", std::span<const VdbGridSpec>(&grid, 1));
  return test::write_file(
      "with_volume.yaml",
      kTinyScene + "  - {type: volume, file: cube.vdb, density_scale: 2, albedo: [0.5, 0.5, 0.5]}\n");
}

// The dynamic loader's own report of what it loads: proof, not a timing.
bool loads_openvdb(const std::filesystem::path& executable, const std::string& arguments, int expected_exit_code) {
  std::string out;
  const int code = run_command("LD_DEBUG=libs " + executable.string() + " " + arguments, &out);
  EXPECT_EQ(code, expected_exit_code) << arguments << "\n" << out.substr(0, 2000);
  return out.find("libopenvdb.so") != std::string::npos;
}

TEST(VdbPlugin, OnlyAScenesVdbFileLoadsOpenVdb) {
  const auto folder = test::scratch_dir();
  const auto scene = test::write_file("scene.yaml", kTinyScene);
  EXPECT_FALSE(loads_openvdb(rtpro_executable(), "--version", 0));
  EXPECT_FALSE(loads_openvdb(rtpro_executable(), "info " + scene.string(), 0));
  EXPECT_FALSE(loads_openvdb(rtpro_executable(), render_args(scene, folder / "plain.exr", "-q"), 0));
  // The control: the same check sees the load when the scene reads a grid.
  const auto volume_scene = scene_with_volume(folder);
  EXPECT_TRUE(loads_openvdb(rtpro_executable(), render_args(volume_scene, folder / "volume.exr", "-q"), 0));
  EXPECT_TRUE(std::filesystem::exists(folder / "volume.exr"));
}

TEST(VdbPlugin, WithoutThePluginVolumesFailWithAClearErrorAndEverythingElseWorks) {
  const auto scratch = test::scratch_dir();
  const auto volume_scene = scene_with_volume(scratch);
  const auto scene = test::write_file("scene.yaml", kTinyScene);
  const auto folder = scratch / "lonely";
  std::filesystem::create_directories(folder);
  const auto lonely = folder / "rtpro";
  std::filesystem::copy_file(rtpro_executable(), lonely, std::filesystem::copy_options::overwrite_existing);
  std::string out;
  EXPECT_EQ(
      run_command(lonely.string() + " render -q " + scene.string() + " -o " + (folder / "plain.exr").string(), &out), 0)
      << out;
  EXPECT_TRUE(std::filesystem::exists(folder / "plain.exr"));
  EXPECT_EQ(
      run_command(lonely.string() + " render -q " + volume_scene.string() + " -o " + (folder / "volume.exr").string(),
                  &out),
      1);
  EXPECT_NE(out.find("librtpro_vdb.so"), std::string::npos) << out;
  EXPECT_EQ(out.find("Segmentation"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(folder / "volume.exr"));
}

}  // namespace vdb_plugin_test
}  // namespace rtpro
