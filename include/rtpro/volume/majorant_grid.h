#pragma once
// Coarse per-cell maxima of a voxel grid (pbrt-v4's MajorantGrid): each cell holds the largest
// value any trilinear lookup inside it can return, so σ_t × that value bounds the extinction
// everywhere in the cell and tracking takes long steps through thin and empty space.
#include "rtpro/core/bbox.h"
#include "rtpro/volume/voxel_grid.h"

#include <array>
#include <cstdint>
#include <vector>

namespace rtpro {

class MajorantGrid {
 public:
  // Cells per axis are chosen from the grid: about kVoxelsPerCell voxels wide, at most kMaxCells.
  static constexpr int kVoxelsPerCell = 8;
  static constexpr int kMaxCells = 64;

  MajorantGrid() = default;
  // Over `grid`'s support (index space); an empty support gives no cells.
  explicit MajorantGrid(const VoxelGrid& grid);

  const BBox& bounds() const { return bounds_; }
  const std::array<int, 3>& resolution() const { return res_; }
  float at(int x, int y, int z) const { return max_[(static_cast<std::size_t>(x) * res_[1] + y) * res_[2] + z]; }
  // The index-space box of cell (x, y, z).
  BBox cell_bounds(int x, int y, int z) const;
  std::uint64_t memory_bytes() const { return max_.capacity() * sizeof(float); }

 private:
  BBox bounds_;
  std::array<int, 3> res_{0, 0, 0};
  std::vector<float> max_;
};

}  // namespace rtpro
