#include "rtpro/volume/majorant_grid.h"

#include "volume_test_grids.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace rtpro {
namespace majorant_grid_test {

// Points in a cell, its faces and corners included (where the neighbouring cells' voxels weigh in).
Vec3 point_in(const BBox& cell, std::mt19937& random) {
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  Vec3 p;
  for (int a = 0; a < 3; ++a) {
    const float u = uniform(random);
    const float t = u < 0.1f ? 0.0f : (u > 0.9f ? 1.0f : uniform(random));
    p[a] = cell.lower[a] + (cell.upper[a] - cell.lower[a]) * t;
  }
  return p;
}

TEST(MajorantGrid, NoLookupInACellExceedsItsMajorant) {
  const VoxelGrid grid = test::random_cloud(-13, 29, 0.05, 7);
  const MajorantGrid majorants(grid);
  const auto res = majorants.resolution();
  ASSERT_GT(res[0], 2);
  std::mt19937 random(11);
  int looked = 0;
  for (int x = 0; x < res[0]; ++x)
    for (int y = 0; y < res[1]; ++y)
      for (int z = 0; z < res[2]; ++z) {
        const BBox cell = majorants.cell_bounds(x, y, z);
        for (int i = 0; i < 300; ++i) {
          const float value = grid.lookup(point_in(cell, random));
          ASSERT_LE(value, majorants.at(x, y, z)) << "cell " << x << " " << y << " " << z;
          ++looked;
        }
        // A bound, but not a loose one: the largest voxel a lookup in the cell reads (those in
        // (lower - 1, upper + 1)), give or take the rounding margin at the cell's faces.
        const auto largest_within = [&](float margin) {
          float largest = 0.0f;
          const auto from = [&](int a) { return static_cast<std::int32_t>(std::floor(cell.lower[a] - 1.0f - margin)); };
          const auto to = [&](int a) { return static_cast<std::int32_t>(std::ceil(cell.upper[a] + 1.0f + margin)); };
          const auto within = [&](std::int32_t v, int a) {
            return v > cell.lower[a] - 1.0f - margin && v < cell.upper[a] + 1.0f + margin;
          };
          for (std::int32_t i = from(0); i <= to(0); ++i)
            for (std::int32_t j = from(1); j <= to(1); ++j)
              for (std::int32_t k = from(2); k <= to(2); ++k)
                if (within(i, 0) && within(j, 1) && within(k, 2)) largest = std::max(largest, grid.voxel(i, j, k));
          return largest;
        };
        EXPECT_GE(majorants.at(x, y, z), largest_within(0.0f));
        EXPECT_LE(majorants.at(x, y, z), largest_within(0.05f)) << "cell " << x << " " << y << " " << z;
      }
  EXPECT_GT(looked, 10'000);
}

TEST(MajorantGrid, CellsAwayFromEveryVoxelAreEmpty) {
  VoxelGrid grid(VoxelBox{{0, 0, 0}, {63, 63, 63}}, 0.0f);
  grid.brick_at({0, 0, 0})[0] = 0.5f;       // voxel (0, 0, 0)
  grid.brick_at({63, 63, 63})[511] = 2.0f;  // voxel (63, 63, 63)
  grid.seal();
  const MajorantGrid majorants(grid);
  const auto res = majorants.resolution();
  EXPECT_EQ(majorants.at(0, 0, 0), 0.5f);
  EXPECT_EQ(majorants.at(res[0] - 1, res[1] - 1, res[2] - 1), 2.0f);
  int empty = 0;
  for (int x = 0; x < res[0]; ++x)
    for (int y = 0; y < res[1]; ++y)
      for (int z = 0; z < res[2]; ++z) empty += majorants.at(x, y, z) == 0.0f;
  EXPECT_EQ(empty, res[0] * res[1] * res[2] - 2);
}

}  // namespace majorant_grid_test
}  // namespace rtpro
