#include "rtpro/volume/voxel_grid.h"

#include "volume_test_grids.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace voxel_grid_test {

void set(VoxelGrid& grid, std::int32_t x, std::int32_t y, std::int32_t z, float value) {
  grid.brick_at({x, y, z})[static_cast<std::size_t>(((x & 7) << 6) | ((y & 7) << 3) | (z & 7))] = value;
}

TEST(VoxelGrid, VoxelCentresReadTheirValuesAndBetweenThemTrilinearly) {
  VoxelGrid grid(VoxelBox{{-9, -1, 0}, {0, 1, 1}}, 0.0f);
  set(grid, -9, 0, 0, 2.0f);
  set(grid, -8, 0, 0, 4.0f);  // the next brick along x: lookups cross brick boundaries
  set(grid, -9, 1, 1, 8.0f);
  grid.seal();
  EXPECT_EQ(grid.voxel(-9, 0, 0), 2.0f);
  EXPECT_EQ(grid.lookup({-9.0f, 0.0f, 0.0f}), 2.0f);
  EXPECT_FLOAT_EQ(grid.lookup({-8.5f, 0.0f, 0.0f}), 3.0f);
  EXPECT_FLOAT_EQ(grid.lookup({-8.75f, 0.0f, 0.0f}), 2.5f);
  EXPECT_FLOAT_EQ(grid.lookup({-9.0f, 0.5f, 0.5f}), 0.25f * (2.0f + 8.0f));
  EXPECT_EQ(grid.brick_count(), 2u);
}

TEST(VoxelGrid, AFilledBoxSetsItsVoxelsWholeBricksAndPartsAlike) {
  // 16³ bricks' worth and a ragged edge: bricks from -8 to 15 on x, parts of bricks on y and z.
  const VoxelBox box{{-8, -3, 2}, {15, 9, 4}};
  VoxelGrid grid(VoxelBox{{-16, -16, -16}, {31, 31, 31}}, 0.0f);
  grid.reserve_bricks(12);
  grid.fill(box, 2.5f);
  grid.seal();
  EXPECT_EQ(grid.brick_count(), 3u * 3u * 1u);
  for (std::int32_t x = -10; x <= 17; ++x)
    for (std::int32_t y = -5; y <= 11; ++y)
      for (std::int32_t z = 0; z <= 6; ++z) {
        const bool inside = x >= -8 && x <= 15 && y >= -3 && y <= 9 && z >= 2 && z <= 4;
        ASSERT_EQ(grid.voxel(x, y, z), inside ? 2.5f : 0.0f) << x << " " << y << " " << z;
      }
  // The support found brick by brick: one voxel around the box.
  EXPECT_EQ(grid.support().lower, Vec3(-9.0f, -4.0f, 1.0f));
  EXPECT_EQ(grid.support().upper, Vec3(16.0f, 10.0f, 5.0f));
}

TEST(VoxelGrid, SupportIsOneVoxelAroundTheValuesAndOutsideItLookupsReadTheBackground) {
  VoxelGrid grid(VoxelBox{{3, 3, 3}, {20, 20, 20}}, 0.0f);
  set(grid, 5, 6, 7, 1.0f);
  set(grid, 17, 6, 7, 1.0f);
  grid.seal();
  EXPECT_EQ(grid.support().lower, Vec3(4.0f, 5.0f, 6.0f));
  EXPECT_EQ(grid.support().upper, Vec3(18.0f, 7.0f, 8.0f));
  EXPECT_EQ(grid.lookup({4.0f, 6.0f, 7.0f}), 0.0f);
  EXPECT_EQ(grid.lookup({1e30f, 6.0f, 7.0f}), 0.0f);
  EXPECT_GT(grid.lookup({4.5f, 6.0f, 7.0f}), 0.0f);
}

TEST(VoxelGrid, MemoryFollowsTheBricksNotTheBox) {
  // Two voxels 1000 voxels apart: two bricks and a table of 126³ entries, not 10⁹ voxels.
  VoxelGrid grid(VoxelBox{{0, 0, 0}, {1000, 1000, 1000}}, 0.0f);
  set(grid, 0, 0, 0, 1.0f);
  set(grid, 1000, 1000, 1000, 1.0f);
  grid.seal();
  EXPECT_EQ(grid.brick_count(), 2u);
  EXPECT_EQ(VoxelGrid::table_entries(grid.active_box()), 126u * 126u * 126u);
  EXPECT_LE(grid.memory_bytes(), VoxelGrid::bytes_for(grid.active_box(), 2) + 4096);
  EXPECT_LT(grid.memory_bytes(), 9'000'000u);
}

TEST(VoxelGrid, SealedGridHoldsItsBricksAndNoSpareCapacity) {
  // Five bricks appended one by one would leave room for eight in a doubling vector.
  VoxelGrid grid(VoxelBox{{0, 0, 0}, {39, 7, 7}}, 0.0f);
  for (std::int32_t x = 0; x < 40; x += 8) set(grid, x, 0, 0, 1.0f);
  grid.seal();
  EXPECT_EQ(grid.brick_count(), 5u);
  EXPECT_EQ(grid.memory_bytes(), VoxelGrid::bytes_for(grid.active_box(), 5));
}

}  // namespace voxel_grid_test
}  // namespace rtpro
