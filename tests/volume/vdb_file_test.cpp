#include "rtpro/volume/vdb_file.h"

#include "rtpro/volume/grid_volume.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace rtpro {
namespace vdb_file_test {

VdbGridSpec density_grid(std::string name = "density") {
  VdbGridSpec spec;
  spec.name = std::move(name);
  spec.voxel_size = 0.5;
  spec.translation = {1.0, 2.0, 3.0};
  spec.voxels = {{{0, 0, 0}, 1.0f}, {{1, 0, 0}, 3.0f}, {{-9, 4, 20}, 0.25f}};
  return spec;
}

std::filesystem::path write_vdb(const std::string& name, const std::vector<VdbGridSpec>& grids) {
  const std::filesystem::path file = test::scratch_dir() / name;
  write_vdb_file(file, grids);
  return file;
}

VdbRequest request_for(const std::filesystem::path& file, std::string density = "density") {
  VdbRequest request;
  request.file = file;
  request.where = SourceLocation{"scene.yaml", 7, 5};
  request.density = std::move(density);
  return request;
}

std::string read_error(const VdbRequest& request) {
  return test::error_message_of<InputError>([&] { read_vdb_grids(request); });
}

TEST(VdbFile, ReadsAFloatGridItsTransformAndItsMemory) {
  const auto file = write_vdb("cloud.vdb", {density_grid(), density_grid("temperature")});
  VdbRequest request = request_for(file);
  request.temperature = "temperature";
  const VdbGrids grids = read_vdb_grids(request);
  EXPECT_EQ(grids.density.voxel(1, 0, 0), 3.0f);
  EXPECT_EQ(grids.density.voxel(-9, 4, 20), 0.25f);
  EXPECT_EQ(grids.density.voxel(2, 0, 0), 0.0f);
  EXPECT_FLOAT_EQ(grids.density.lookup({0.5f, 0.0f, 0.0f}), 2.0f);
  EXPECT_EQ(grids.density.active_voxels, 3u);
  ASSERT_TRUE(grids.temperature.has_value());
  EXPECT_FALSE(grids.emission.has_value());
  // Index (2, 0, 0) is 2 × 0.5 from the translation (1, 2, 3).
  EXPECT_EQ(grids.density.index_to_medium.apply_point({2.0f, 0.0f, 0.0f}), Vec3(2.0f, 2.0f, 3.0f));
  EXPECT_EQ(grids.memory.active_voxels, 3u);
  EXPECT_EQ(grids.memory.file_bytes, std::filesystem::file_size(file));
  // Two grids of two bricks each, and the estimate from the metadata bounds what was read.
  EXPECT_GE(grids.memory.bytes, 4u * VoxelGrid::kBrickVoxels * sizeof(float));
  EXPECT_GE(estimate_vdb_bytes(request), grids.memory.bytes);
}

TEST(VdbFile, ReadsDoubleGridsAndActiveTiles) {
  VdbGridSpec spec = density_grid();
  spec.type = "double";
  spec.tile_origin = VoxelCoord{16, 0, 0};
  spec.tile_value = 0.5f;
  const VdbGrids grids = read_vdb_grids(request_for(write_vdb("tiles.vdb", {spec})));
  EXPECT_EQ(grids.density.voxel(1, 0, 0), 3.0f);
  EXPECT_EQ(grids.density.voxel(16, 0, 0), 0.5f);
  EXPECT_EQ(grids.density.voxel(23, 7, 7), 0.5f);
  EXPECT_EQ(grids.density.voxel(24, 7, 7), 0.0f);
  EXPECT_EQ(grids.density.active_voxels, 3u + 512u);
}

TEST(VdbFile, PlacingComposesTheFilesTransformWithTheScenes) {
  const VdbGrids grids = read_vdb_grids(request_for(write_vdb("placed.vdb", {density_grid()})));
  const GridVolume volume = place_grid_volume(grids, Affine::translate({10.0f, 0.0f, 0.0f}), {});
  // Index (1, 0, 0) sits at (1.5, 2, 3) in the file's space, (11.5, 2, 3) in the scene.
  EXPECT_FLOAT_EQ(volume.density.at({11.5f, 2.0f, 3.0f}), 3.0f);
  EXPECT_FLOAT_EQ(volume.density.at({11.25f, 2.0f, 3.0f}), 2.0f);
  EXPECT_EQ(volume.density.at({-50.0f, 2.0f, 3.0f}), 0.0f);
  EXPECT_TRUE(volume.world_bounds().lower.x < 11.0f && volume.world_bounds().upper.x > 11.5f);
  EXPECT_GT(volume.memory.bytes, grids.memory.bytes);  // the majorants too
}

TEST(VdbFile, AMissingFileIsAnInputErrorAtTheEntry) {
  const std::string message = read_error(request_for(test::scratch_dir() / "absent.vdb"));
  EXPECT_NE(message.find("scene.yaml:7:5"), std::string::npos) << message;
  EXPECT_NE(message.find("absent.vdb: no such OpenVDB file"), std::string::npos) << message;
}

TEST(VdbFile, AFileThatIsNotOpenVdbIsAnInputError) {
  const std::string message = read_error(request_for(test::write_file("text.vdb", "not a vdb file\n")));
  EXPECT_NE(message.find("text.vdb: not a readable OpenVDB file"), std::string::npos) << message;
}

TEST(VdbFile, AMissingGridListsTheGridsThatAreThere) {
  VdbGridSpec velocity = density_grid("vel");
  velocity.type = "vec3s";
  const auto file = write_vdb("named.vdb", {density_grid("densty"), velocity});
  const std::string message = read_error(request_for(file));
  EXPECT_NE(message.find("named.vdb has no grid named 'density'; its grids: densty (float), vel (vec3s)"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("densty"), message.rfind("densty")) << "a suggestion: " << message;
  EXPECT_EQ(test::error_message_of<InputError>([&] { estimate_vdb_bytes(request_for(file)); }), message);
}

TEST(VdbFile, NonFloatGridsAndLevelSetsAreRefusedNamingTheGrid) {
  for (const char* type : {"vec3s", "int32"}) {
    VdbGridSpec spec = density_grid();
    spec.type = type;
    const std::string message = read_error(request_for(write_vdb(std::string(type) + ".vdb", {spec})));
    EXPECT_NE(message.find(": grid 'density' holds " + std::string(type) + " values"), std::string::npos) << message;
  }
  VdbGridSpec level_set = density_grid();
  level_set.level_set = true;
  const std::string message = read_error(request_for(write_vdb("sdf.vdb", {level_set})));
  EXPECT_NE(message.find("sdf.vdb: grid 'density' is a level set"), std::string::npos) << message;
}

TEST(VdbFile, AnEmptyGridIsRefused) {
  VdbGridSpec empty = density_grid();
  empty.voxels.clear();
  const auto file = write_vdb("empty.vdb", {empty});
  const std::string message = read_error(request_for(file));
  EXPECT_NE(message.find("empty.vdb: grid 'density' has no active voxels"), std::string::npos) << message;
  EXPECT_EQ(test::error_message_of<InputError>([&] { estimate_vdb_bytes(request_for(file)); }), message);
}

TEST(VdbFile, NegativeAndNonFiniteValuesAreRefusedWithTheFirstVoxel) {
  for (const float bad : {-0.5f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    VdbGridSpec spec = density_grid();
    spec.voxels.push_back({{3, -2, 1}, bad});
    spec.voxels.push_back({{4, -2, 1}, -1.0f});
    const std::string message = read_error(request_for(write_vdb("bad.vdb", {spec})));
    EXPECT_NE(message.find("bad.vdb: grid 'density' has 2 voxels that are negative or not finite (the first: "),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("at [3, -2, 1]"), std::string::npos) << message;
  }
}

TEST(VdbFile, GridsLargerThanTheBudgetAreRefusedWhateverTheFilesStatisticsSay) {
  VdbGridSpec spec = density_grid();
  spec.tile_origin = VoxelCoord{128, 0, 0};
  spec.tile_value = 0.5f;
  spec.tile_level = 2;  // 128³ voxels: 4,096 bricks, 8 MiB
  const auto file = write_vdb("tile.vdb", {spec});
  VdbRequest request = request_for(file);
  EXPECT_GT(estimate_vdb_bytes(request), 8u << 20);
  request.max_bytes = 4u << 20;
  std::string message = read_error(request);
  EXPECT_NE(message.find("tile.vdb: grid 'density' holds 2097155 active voxels, "), std::string::npos) << message;
  EXPECT_NE(message.find("more than the 4.0 MiB left of the memory budget; raise"), std::string::npos) << message;
  // Statistics that claim three voxels in a small box: the estimate believes them, the read does not.
  std::string bytes = test::read_file(file);
  const auto patch = [&](const std::string& name, const void* value, std::size_t size) {
    const std::size_t at = bytes.find(name);
    ASSERT_NE(at, std::string::npos) << name;
    const std::size_t value_at = at + name.size() + 4 + 5 + 4;  // the type "int64"/"vec3i", its size
    bytes.replace(value_at, size, static_cast<const char*>(value), size);
  };
  const std::int64_t three = 3;
  const std::int32_t small_box[3] = {1, 4, 20};
  patch("file_voxel_count", &three, sizeof three);
  patch("file_bbox_max", small_box, sizeof small_box);
  request.file = test::write_file("lying.vdb", bytes);
  EXPECT_LT(estimate_vdb_bytes(request), 4u << 20);
  message = read_error(request);
  EXPECT_NE(message.find("lying.vdb: grid 'density' holds 2097155 active voxels"), std::string::npos) << message;
  EXPECT_NE(message.find("(the file's statistics claim less)"), std::string::npos) << message;
}

TEST(VdbFile, TheEmissionGridIsCheckedLikeTheDensity) {
  VdbGridSpec emission = density_grid("heat");
  emission.voxels.push_back({{2, 2, 2}, -3.0f});
  VdbRequest request = request_for(write_vdb("emit.vdb", {density_grid(), emission}));
  request.emission = "heat";
  EXPECT_NE(read_error(request).find("emit.vdb: grid 'heat' has 1 voxel that is negative"), std::string::npos);
  request.emission = "flame";
  EXPECT_NE(read_error(request).find("no grid named 'flame'"), std::string::npos);
}

}  // namespace vdb_file_test
}  // namespace rtpro
