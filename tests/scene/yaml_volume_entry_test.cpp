// World `volume` entries: what the parser reads and refuses, and their grids read, placed and
// counted in the memory estimate when the scene is built.
#include "rtpro/core/memory_budget.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/render_cost.h"
#include "rtpro/scene/scene_parser.h"
#include "rtpro/volume/vdb_file.h"
#include "scene_text_error.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro::test {
namespace yaml_volume_entry_test {

// A 2-voxel density grid (and a temperature grid) in scratch_dir()/smoke.vdb.
std::string write_smoke() {
  VdbGridSpec density;
  density.name = "density";
  density.voxels = {{{0, 0, 0}, 1.0f}, {{1, 0, 0}, 0.5f}};
  VdbGridSpec temperature = density;
  temperature.name = "temperature";
  const std::filesystem::path file = scratch_dir() / "smoke.vdb";
  const VdbGridSpec grids[] = {density, temperature};
  write_vdb_file(file, grids);
  return file.string();
}

TEST(YamlVolumeEntry, ReadsEveryKey) {
  const std::string vdb = write_smoke();
  const SceneDescription scene = parse_scene_text(
      with_world("  - {type: volume, file: " + vdb +
                 ", grid: density, density_scale: 4, albedo: [0.9, 0.8, 0.7], anisotropy: -0.3,\n"
                 "     temperature_grid: temperature, temperature_scale: 1000, transform: {translate: [0, 1, 0]}}\n"),
      "test.yaml");
  ASSERT_EQ(scene.volumes.size(), 1u);
  const VolumeDesc& v = scene.volumes[0];
  EXPECT_EQ(v.file, vdb);
  EXPECT_EQ(v.where.line, 4);
  EXPECT_EQ(v.grid, "density");
  EXPECT_EQ(v.density_scale, 4.0f);
  EXPECT_EQ(v.albedo, Color(0.9f, 0.8f, 0.7f));
  EXPECT_EQ(v.anisotropy, -0.3f);
  EXPECT_EQ(v.temperature_grid, "temperature");
  EXPECT_EQ(v.temperature_scale, 1000.0f);
  EXPECT_TRUE(v.emission_grid.empty());
  EXPECT_EQ(v.transform.apply_point({0, 0, 0}), Vec3(0, 1, 0));
  EXPECT_TRUE(scene.world.spheres.empty());
}

TEST(YamlVolumeEntry, RefusesValuesOutOfRangeAtTheirPosition) {
  const std::string vdb = write_smoke();
  const std::string entry = "  - {type: volume, file: " + vdb;
  const std::string albedo = with_world(entry + ", albedo: [1.2, 0, 0]}\n");
  EXPECT_SCENE_ERROR(albedo, at(albedo, 4, "[1.2"), {"volume.albedo", "between 0 and 1"});
  const std::string g = with_world(entry + ", anisotropy: 1}\n");
  EXPECT_SCENE_ERROR(g, at(g, 4, "1}"), {"volume.anisotropy", "strictly between -1 and 1"});
  const std::string scale = with_world(entry + ", density_scale: -2}\n");
  EXPECT_SCENE_ERROR(scale, at(scale, 4, "-2"), {"volume.density_scale"});
  const std::string lonely = with_world(entry + ", emission_scale: 3}\n");
  EXPECT_SCENE_ERROR(lonely, at(lonely, 4, "3}"), {"volume.emission_scale needs an emission_grid"});
  const std::string typo = with_world(entry + ", albedoo: [1, 1, 1]}\n");
  EXPECT_SCENE_ERROR(typo, at(typo, 4, "albedoo"), {"albedoo", "albedo"});
}

TEST(YamlVolumeEntry, RefusesMissingAndNonVdbFilesAndVolumesInObjects) {
  const std::string missing = with_world("  - {type: volume, file: " + (scratch_dir() / "gone.vdb").string() + "}\n");
  EXPECT_SCENE_ERROR(missing, at(missing, 4, "/"), {"volume.file: volume file", "gone.vdb' not found"});
  const std::string obj = with_world("  - {type: volume, file: " + write_file("cloud.obj", "").string() + "}\n");
  EXPECT_SCENE_ERROR(obj, at(obj, 4, "/"), {"is not an OpenVDB file (.vdb)"});
  const std::string object = kHeader + "objects:\n  puff:\n    - {type: volume, file: " + write_smoke() + "}\n";
  EXPECT_SCENE_ERROR(object, at(object, 5, "{"), {"object 'puff': a volume entry belongs in world:"});
}

TEST(YamlVolumeEntry, BuildingReadsAndPlacesTheGrids) {
  const std::string vdb = write_smoke();
  const SceneDescription description = parse_scene_text(
      with_world("  - {type: volume, file: " + vdb +
                 ", density_scale: 2, albedo: [0.75, 0.5, 0.25], transform: {translate: [5, 0, 0]}}\n"),
      "test.yaml");
  const RenderScene scene = build_render_scene(description);
  ASSERT_EQ(scene.volumes.size(), 1u);
  const GridMedium& medium = std::get<GridMedium>(scene.media[scene.volumes[0]]);
  EXPECT_EQ(medium.sigma_s, Color(1.5f, 1.0f, 0.5f));
  EXPECT_EQ(medium.sigma_a, Color(0.5f, 1.0f, 1.5f));
  EXPECT_FLOAT_EQ(medium.grid->density.at({5.5f, 0.0f, 0.0f}), 0.75f);
  EXPECT_EQ(medium.grid->memory.active_voxels, 2u);
  EXPECT_GT(estimate_render_cost(description).volume_bytes, 0u);
}

TEST(YamlVolumeEntry, AVolumeIsAnInterfaceBoxIntoItsMediumWoundOutwardEvenWhenMirrored) {
  const std::string vdb = write_smoke();
  for (const std::string scale : {"[2, 2, 2]", "[-2, 1, 1]"}) {
    const SceneDescription description = parse_scene_text(
        with_world("  - {type: volume, file: " + vdb + ", transform: {scale: " + scale + "}}\n"), "test.yaml");
    const RenderScene scene = build_render_scene(description);
    ASSERT_EQ(scene.top.geometries.size(), 1u) << scale;
    const TriangleMesh& box = std::get<TriangleMesh>(scene.top.geometries[0]);
    ASSERT_EQ(box.triangles.size(), 12u);
    const Material& boundary = scene.materials[box.material];
    EXPECT_TRUE(boundary.index_matched);
    EXPECT_EQ(boundary.interior, scene.volumes[0]);
    const BBox bounds = box.bounds();
    const Vec3 centre = (bounds.lower + bounds.upper) * 0.5f;
    // The majorant box in index space is [-1, 2] x [-1, 1]², half a voxel wider each way.
    EXPECT_NEAR(bounds.extent().y * bounds.extent().z, scale == "[2, 2, 2]" ? 36.0f : 9.0f, 1e-4f) << scale;
    for (const TriangleIndices& t : box.triangles) {
      const Vec3 v0 = box.vertex(t.v0), v1 = box.vertex(t.v1), v2 = box.vertex(t.v2);
      EXPECT_GT(dot(cross(v1 - v0, v2 - v0), (v0 + v1 + v2) * (1.0f / 3.0f) - centre), 0.0f) << scale;
    }
  }
}

TEST(YamlVolumeEntry, GridErrorsNameTheFileAndGridAtTheEntry) {
  const std::string text = with_world("  - {type: volume, file: " + write_smoke() + ", grid: densty}\n");
  const SceneDescription description = parse_scene_text(text, "test.yaml");
  for (const std::string& message : {error_message_of<InputError>([&] { build_render_scene(description); }),
                                     error_message_of<InputError>([&] { estimate_render_cost(description); })}) {
    EXPECT_NE(message.find("test.yaml:4:"), std::string::npos) << message;
    EXPECT_NE(message.find("smoke.vdb has no grid named 'densty'; its grids: density (float), temperature (float)"),
              std::string::npos)
        << message;
  }
}

TEST(YamlVolumeEntry, AGridLargerThanTheBudgetIsRefusedBeforeItIsRead) {
  // One tile of 128³ active voxels: a file of a few kilobytes whose grid would take 8 MiB.
  VdbGridSpec big;
  big.name = "density";
  big.tile_origin = VoxelCoord{0, 0, 0};
  big.tile_value = 0.5f;
  big.tile_level = 2;
  const std::filesystem::path file = scratch_dir() / "big.vdb";
  write_vdb_file(file, std::span<const VdbGridSpec>(&big, 1));
  const SceneDescription description =
      parse_scene_text(with_world("  - {type: volume, file: " + file.string() + "}\n"), "test.yaml");
  const RenderCost cost = estimate_render_cost(description);
  EXPECT_GT(cost.volume_bytes, std::uint64_t{8} << 20);
  EXPECT_LT(std::filesystem::file_size(file), 100'000u);
  const std::string message = error_message_of<InputError>(
      [&] { check_render_cost(cost, std::uint64_t{4} << 20, "--max-memory 4", "test.yaml"); });
  EXPECT_NE(message.find("volumes "), std::string::npos) << message;
  EXPECT_NE(message.find("--max-memory"), std::string::npos) << message;
}

}  // namespace yaml_volume_entry_test
}  // namespace rtpro::test
