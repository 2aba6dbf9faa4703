// A world `volume` entry through the real binary: `rtpro info` lists its grid's memory against the
// file's, and bad grids or a grid over --max-memory exit 2, naming the file and grid, before a
// render starts (and before an output is written).
#include "rtpro/volume/vdb_file.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace volume_info_test {

using test::expect_rtpro_answer;
using test::render_args;
using test::run_rtpro;

std::filesystem::path volume_scene(const std::string& entry) {
  return test::write_file("scene.yaml",
                          "rtpro: 1\n"
                          "camera: {position: [0, 0, 40], look_at: [0, 0, 0], resolution: [8, 8]}\n"
                          "lights: [{type: point, position: [2, 2, 4], intensity: 1}]\n"
                          "world:\n"
                          "  - " +
                              entry + "\n");
}

void write_cloud(const std::filesystem::path& file, const std::string& name, float value, int tile_level = 1) {
  VdbGridSpec grid;
  grid.name = name;
  grid.voxels = {{{0, 0, 0}, 1.0f}, {{5, 5, 5}, value}};
  grid.tile_origin = VoxelCoord{64, 0, 0};
  grid.tile_value = 0.25f;
  grid.tile_level = tile_level;
  write_vdb_file(file, std::span<const VdbGridSpec>(&grid, 1));
}

TEST(VolumeInfo, InfoListsTheGridsMemoryPerActiveVoxel) {
  write_cloud(test::scratch_dir() / "cloud.vdb", "density", 0.5f);
  const auto scene = volume_scene("{type: volume, file: cloud.vdb, density_scale: 2}");
  const std::string out = run_rtpro("info " + scene.string(), 0);
  EXPECT_NE(out.find("grid 'density': 514 active voxels in 72x8x8"), std::string::npos) << out;
  EXPECT_NE(out.find("bytes per active voxel; the file"), std::string::npos) << out;
}

TEST(VolumeInfo, BadGridsExitTwoNamingFileAndGridBeforeRendering) {
  const auto dir = test::scratch_dir();
  write_cloud(dir / "cloud.vdb", "density", -1.0f);
  const auto negative = volume_scene("{type: volume, file: cloud.vdb}");
  std::string out = expect_rtpro_answer(render_args(negative, dir / "a.png") + " --progress never", 2,
                                        "cloud.vdb: grid 'density' has 1 voxel that is negative or not finite");
  EXPECT_NE(out.find(negative.string() + ":5:"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
  const auto missing = volume_scene("{type: volume, file: cloud.vdb, grid: smoke}");
  expect_rtpro_answer("info " + missing.string(), 2, "cloud.vdb has no grid named 'smoke'; its grids: density (float)");
}

TEST(VolumeInfo, AGridOverMaxMemoryIsRefusedFromItsMetadata) {
  const auto dir = test::scratch_dir();
  write_cloud(dir / "cloud.vdb", "density", 0.5f, 3);  // a tile of 4096³ voxels
  const auto scene = volume_scene("{type: volume, file: cloud.vdb}");
  const std::string out =
      expect_rtpro_answer(render_args(scene, dir / "a.png") + " --progress never --max-memory 512", 2, "volumes ");
  EXPECT_NE(out.find("more than the memory budget"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
}

}  // namespace volume_info_test
}  // namespace rtpro
