#pragma once
// Small voxel grids built in memory for the volume tests: a seeded random sparse cloud and the
// grids the OpenVDB tests write.
#include "rtpro/volume/voxel_grid.h"

#include <cstdint>
#include <random>

namespace rtpro::test {

// Voxels in [lo, hi]³ of which about `fill` are set to random densities in (0, 1], seeded; the
// rest stay background 0. Whole bricks of the box are touched, so most lookups see values.
inline VoxelGrid random_cloud(std::int32_t lo, std::int32_t hi, double fill, std::uint32_t seed) {
  VoxelGrid grid(VoxelBox{{lo, lo, lo}, {hi, hi, hi}}, 0.0f);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (std::int32_t x = lo; x <= hi; ++x)
    for (std::int32_t y = lo; y <= hi; ++y)
      for (std::int32_t z = lo; z <= hi; ++z) {
        if (uniform(random) >= fill) continue;
        grid.brick_at({x, y, z})[static_cast<std::size_t>(((x & 7) << 6) | ((y & 7) << 3) | (z & 7))] =
            1.0f - uniform(random);
      }
  grid.seal();
  return grid;
}

}  // namespace rtpro::test
