#include "rtpro/volume/majorant_grid.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

namespace {

// The cells along one axis whose span meets the open interval (lo, hi), clamped to the grid, and
// their neighbours when (lo, hi) ends within a thousandth of a cell of them: the cell index is
// rounded, as is the position a tracker computes along a ray, and the bound must hold for both.
struct CellRange {
  int first, last;
};

CellRange cells_meeting(float lo, float hi, float origin, float width, int cells) {
  constexpr float kMargin = 1e-3f;
  const auto clamp_cell = [&](float c) { return std::clamp(static_cast<int>(std::floor(c)), 0, cells - 1); };
  return {clamp_cell((lo - origin) / width - kMargin), clamp_cell((hi - origin) / width + kMargin)};
}

}  // namespace

MajorantGrid::MajorantGrid(const VoxelGrid& grid) : bounds_(grid.support()) {
  if (bounds_.empty()) return;
  const Vec3 extent = bounds_.extent();
  for (int a = 0; a < 3; ++a)
    res_[a] = std::clamp(static_cast<int>(std::ceil(extent[a] / kVoxelsPerCell)), 1, kMaxCells);
  max_.assign(static_cast<std::size_t>(res_[0]) * res_[1] * res_[2], 0.0f);
  // Outside its bricks a grid reads the background, which any cell may see.
  if (grid.background() > 0.0f) std::fill(max_.begin(), max_.end(), grid.background());

  Vec3 width;
  for (int a = 0; a < 3; ++a) width[a] = extent[a] / static_cast<float>(res_[a]);
  // A lookup at p reads voxels floor(p) and floor(p) + 1 on each axis, so voxel v weighs in on the
  // open interval (v - 1, v + 1): every cell meeting it may see v's value.
  grid.for_each_brick([&](const VoxelCoord& origin, std::span<const float> values) {
    for (int i = 0; i < VoxelGrid::kBrickVoxels; ++i) {
      const float value = values[static_cast<std::size_t>(i)];
      if (!(value > 0.0f)) continue;
      const VoxelCoord v{origin[0] + (i >> 6), origin[1] + ((i >> 3) & 7), origin[2] + (i & 7)};
      CellRange range[3];
      bool outside = false;
      for (int a = 0; a < 3; ++a) {
        const float lo = static_cast<float>(v[a] - 1), hi = static_cast<float>(v[a] + 1);
        outside = outside || hi <= bounds_.lower[a] || lo >= bounds_.upper[a];
        range[a] = cells_meeting(lo, hi, bounds_.lower[a], width[a], res_[a]);
      }
      if (outside) continue;
      for (int x = range[0].first; x <= range[0].last; ++x)
        for (int y = range[1].first; y <= range[1].last; ++y)
          for (int z = range[2].first; z <= range[2].last; ++z) {
            float& cell = max_[(static_cast<std::size_t>(x) * res_[1] + y) * res_[2] + z];
            cell = std::max(cell, value);
          }
    }
  });
}

BBox MajorantGrid::cell_bounds(int x, int y, int z) const {
  const int cell[3] = {x, y, z};
  BBox box;
  for (int a = 0; a < 3; ++a) {
    const float width = (bounds_.upper[a] - bounds_.lower[a]) / static_cast<float>(res_[a]);
    box.lower[a] = bounds_.lower[a] + width * static_cast<float>(cell[a]);
    box.upper[a] =
        cell[a] + 1 == res_[a] ? bounds_.upper[a] : bounds_.lower[a] + width * static_cast<float>(cell[a] + 1);
  }
  return box;
}

}  // namespace rtpro
