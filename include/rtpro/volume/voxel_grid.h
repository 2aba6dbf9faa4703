#pragma once
// A scalar voxel grid as the renderer reads it (density, emission, temperature): OpenVDB's leaf
// nodes copied into 8³ bricks, found through one table over the bricks of the active bounding box,
// so memory follows the active voxels (not the box's volume) and a lookup is two array reads.
// Values sit at integer index coordinates (voxel centres, as OpenVDB's); `index_to_medium` is the
// file's own transform from index space to the grid's world (the volume's "medium" space).
#include "rtpro/core/bbox.h"
#include "rtpro/core/transform.h"
#include "rtpro/core/vec3.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

// Integer voxel coordinates, and an inclusive box of them.
using VoxelCoord = std::array<std::int32_t, 3>;
struct VoxelBox {
  VoxelCoord lo{0, 0, 0}, hi{-1, -1, -1};
  bool empty() const { return lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]; }
  // Voxels along each axis (0 when empty).
  std::array<std::uint64_t, 3> dims() const;
  std::uint64_t voxel_count() const;  // saturating
};

class VoxelGrid {
 public:
  static constexpr int kBrickLog2 = 3;  // OpenVDB's leaf nodes are 8³ too, so a leaf is one brick
  static constexpr int kBrickSide = 1 << kBrickLog2;
  static constexpr int kBrickVoxels = kBrickSide * kBrickSide * kBrickSide;

  VoxelGrid() = default;
  // An empty grid whose bricks may cover `active` (the active voxels' box); every voxel not in a
  // brick reads `background`.
  VoxelGrid(const VoxelBox& active, float background);

  // The bricks `active` touches, and the bytes of the table and of `bricks` bricks: what a grid
  // will need, known before its values are read.
  static std::uint64_t table_entries(const VoxelBox& active);
  static std::uint64_t bytes_for(const VoxelBox& active, std::uint64_t bricks);

  // The 512 values of the brick holding voxel `origin` (made on first use, filled with the
  // background), in OpenVDB's leaf order: offset = (x & 7) << 6 | (y & 7) << 3 | (z & 7).
  std::span<float> brick_at(const VoxelCoord& origin);
  // Room for `bricks` bricks, when their number is known before they are made (no doubling of
  // the values while they are appended, nothing to give back when sealed).
  void reserve_bricks(std::uint64_t bricks);
  // Sets every voxel of `box` to `value`: whole bricks at once (a tile of OpenVDB's covers whole
  // leaves), voxel by voxel where the box covers part of a brick.
  void fill(const VoxelBox& box, float value);
  // Called once the bricks are filled: finds the voxels that differ from the background, which
  // bound support().
  void seal();

  float voxel(std::int32_t x, std::int32_t y, std::int32_t z) const {
    const std::int32_t bx = (x >> kBrickLog2) - brick_lo_[0], by = (y >> kBrickLog2) - brick_lo_[1],
                       bz = (z >> kBrickLog2) - brick_lo_[2];
    if (bx < 0 || by < 0 || bz < 0 || bx >= brick_dims_[0] || by >= brick_dims_[1] || bz >= brick_dims_[2])
      return background_;
    const std::uint32_t brick =
        table_[(static_cast<std::size_t>(bx) * brick_dims_[1] + static_cast<std::size_t>(by)) * brick_dims_[2] +
               static_cast<std::size_t>(bz)];
    if (brick == kNoBrick) return background_;
    return values_[static_cast<std::size_t>(brick) * kBrickVoxels +
                   static_cast<std::size_t>(((x & 7) << 6) | ((y & 7) << 3) | (z & 7))];
  }

  // Trilinear interpolation at a point in index space (OpenVDB's BoxSampler).
  float lookup(const Vec3& p) const;

  // The box of active voxels, and the box outside which every trilinear lookup reads only the
  // background: one voxel around the voxels that differ from it (empty when none do).
  const VoxelBox& active_box() const { return active_; }
  const BBox& support() const { return support_; }
  float background() const { return background_; }
  std::uint64_t brick_count() const { return values_.size() / kBrickVoxels; }
  std::uint64_t memory_bytes() const;
  // Calls visit(origin, values) for every brick, origin its first voxel.
  template <typename Visit>
  void for_each_brick(Visit&& visit) const;

  Affine index_to_medium;
  std::uint64_t active_voxels = 0;  // as the file counts them (tiles included)

 private:
  static constexpr std::uint32_t kNoBrick = ~0u;
  VoxelBox active_;
  BBox support_;
  std::array<std::int32_t, 3> brick_lo_{0, 0, 0}, brick_dims_{0, 0, 0};
  std::vector<std::uint32_t> table_;  // brick index per brick of the box, x-major; kNoBrick: background
  std::vector<VoxelCoord> origins_;   // per brick
  std::vector<float> values_;         // kBrickVoxels per brick
  float background_ = 0.0f;
};

template <typename Visit>
void VoxelGrid::for_each_brick(Visit&& visit) const {
  for (std::size_t b = 0; b < origins_.size(); ++b)
    visit(origins_[b], std::span<const float>(values_.data() + b * kBrickVoxels, kBrickVoxels));
}

}  // namespace rtpro
