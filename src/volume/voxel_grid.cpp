#include "rtpro/volume/voxel_grid.h"

#include "rtpro/core/memory_budget.h"

#include <algorithm>

namespace rtpro {

namespace {

std::int32_t brick_of(std::int32_t voxel) { return voxel >> VoxelGrid::kBrickLog2; }

}  // namespace

std::array<std::uint64_t, 3> VoxelBox::dims() const {
  if (empty()) return {0, 0, 0};
  std::array<std::uint64_t, 3> d{};
  for (int a = 0; a < 3; ++a) d[a] = static_cast<std::uint64_t>(std::int64_t{hi[a]} - lo[a] + 1);
  return d;
}

std::uint64_t VoxelBox::voxel_count() const {
  const auto d = dims();
  return saturating_multiply(saturating_multiply(d[0], d[1]), d[2]);
}

VoxelGrid::VoxelGrid(const VoxelBox& active, float background) : active_(active), background_(background) {
  if (active.empty()) return;
  for (int a = 0; a < 3; ++a) {
    brick_lo_[a] = brick_of(active.lo[a]);
    brick_dims_[a] = brick_of(active.hi[a]) - brick_lo_[a] + 1;
  }
  table_.assign(table_entries(active), kNoBrick);
}

std::uint64_t VoxelGrid::table_entries(const VoxelBox& active) {
  if (active.empty()) return 0;
  std::uint64_t entries = 1;
  for (int a = 0; a < 3; ++a)
    entries =
        saturating_multiply(entries, static_cast<std::uint64_t>(brick_of(active.hi[a]) - brick_of(active.lo[a]) + 1));
  return entries;
}

std::uint64_t VoxelGrid::bytes_for(const VoxelBox& active, std::uint64_t bricks) {
  const std::uint64_t per_brick = kBrickVoxels * sizeof(float) + sizeof(VoxelCoord);
  return saturating_add(saturating_multiply(table_entries(active), sizeof(std::uint32_t)),
                        saturating_multiply(bricks, per_brick));
}

std::span<float> VoxelGrid::brick_at(const VoxelCoord& voxel) {
  std::size_t slot = 0;
  for (int a = 0; a < 3; ++a)
    slot =
        slot * static_cast<std::size_t>(brick_dims_[a]) + static_cast<std::size_t>(brick_of(voxel[a]) - brick_lo_[a]);
  if (table_[slot] == kNoBrick) {
    table_[slot] = static_cast<std::uint32_t>(origins_.size());
    origins_.push_back({voxel[0] & ~(kBrickSide - 1), voxel[1] & ~(kBrickSide - 1), voxel[2] & ~(kBrickSide - 1)});
    values_.resize(values_.size() + kBrickVoxels, background_);
  }
  return {values_.data() + static_cast<std::size_t>(table_[slot]) * kBrickVoxels, kBrickVoxels};
}

float VoxelGrid::lookup(const Vec3& p) const {
  const float fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
  // Beyond the support every corner is background (and far points would overflow the int cast).
  const BBox& box = support_;
  if (!(p.x > box.lower.x && p.y > box.lower.y && p.z > box.lower.z && p.x < box.upper.x && p.y < box.upper.y &&
        p.z < box.upper.z))
    return background_;
  const auto x = static_cast<std::int32_t>(fx), y = static_cast<std::int32_t>(fy), z = static_cast<std::int32_t>(fz);
  const float tx = p.x - fx, ty = p.y - fy, tz = p.z - fz;
  auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
  const float c00 = lerp(voxel(x, y, z), voxel(x + 1, y, z), tx);
  const float c10 = lerp(voxel(x, y + 1, z), voxel(x + 1, y + 1, z), tx);
  const float c01 = lerp(voxel(x, y, z + 1), voxel(x + 1, y, z + 1), tx);
  const float c11 = lerp(voxel(x, y + 1, z + 1), voxel(x + 1, y + 1, z + 1), tx);
  return lerp(lerp(c00, c10, ty), lerp(c01, c11, ty), tz);
}

void VoxelGrid::reserve_bricks(std::uint64_t bricks) {
  origins_.reserve(static_cast<std::size_t>(bricks));
  values_.reserve(static_cast<std::size_t>(bricks) * kBrickVoxels);
}

void VoxelGrid::fill(const VoxelBox& box, float value) {
  if (box.empty()) return;
  for (std::int32_t bx = box.lo[0] & ~(kBrickSide - 1); bx <= box.hi[0]; bx += kBrickSide)
    for (std::int32_t by = box.lo[1] & ~(kBrickSide - 1); by <= box.hi[1]; by += kBrickSide)
      for (std::int32_t bz = box.lo[2] & ~(kBrickSide - 1); bz <= box.hi[2]; bz += kBrickSide) {
        const std::span<float> brick = brick_at({bx, by, bz});
        const VoxelCoord lo{std::max(bx, box.lo[0]), std::max(by, box.lo[1]), std::max(bz, box.lo[2])};
        const VoxelCoord hi{std::min(bx + kBrickSide - 1, box.hi[0]), std::min(by + kBrickSide - 1, box.hi[1]),
                            std::min(bz + kBrickSide - 1, box.hi[2])};
        if (lo == VoxelCoord{bx, by, bz} && hi == VoxelCoord{bx + 7, by + 7, bz + 7}) {
          std::fill(brick.begin(), brick.end(), value);
          continue;
        }
        for (std::int32_t x = lo[0]; x <= hi[0]; ++x)
          for (std::int32_t y = lo[1]; y <= hi[1]; ++y)
            for (std::int32_t z = lo[2]; z <= hi[2]; ++z)
              brick[static_cast<std::size_t>(((x & 7) << 6) | ((y & 7) << 3) | (z & 7))] = value;
      }
}

void VoxelGrid::seal() {
  BBox differing;
  for_each_brick([&](const VoxelCoord& origin, std::span<const float> values) {
    // The brick's differing voxels' box in its own coordinates, then one extension per brick.
    int lo[3] = {kBrickSide, kBrickSide, kBrickSide}, hi[3] = {-1, -1, -1};
    for (int i = 0; i < kBrickVoxels; ++i) {
      if (values[static_cast<std::size_t>(i)] == background_) continue;
      const int at[3] = {i >> 6, (i >> 3) & 7, i & 7};
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], at[a]);
        hi[a] = std::max(hi[a], at[a]);
      }
    }
    if (hi[0] < 0) return;
    differing.extend(Vec3(static_cast<float>(origin[0] + lo[0]), static_cast<float>(origin[1] + lo[1]),
                          static_cast<float>(origin[2] + lo[2])));
    differing.extend(Vec3(static_cast<float>(origin[0] + hi[0]), static_cast<float>(origin[1] + hi[1]),
                          static_cast<float>(origin[2] + hi[2])));
  });
  support_ = differing.empty() ? BBox{} : BBox{differing.lower - Vec3(1.0f), differing.upper + Vec3(1.0f)};
  // The bricks were appended one by one: give back what their vectors' doubling reserved.
  values_.shrink_to_fit();
  origins_.shrink_to_fit();
}

std::uint64_t VoxelGrid::memory_bytes() const {
  return table_.capacity() * sizeof(std::uint32_t) + origins_.capacity() * sizeof(VoxelCoord) +
         values_.capacity() * sizeof(float);
}

}  // namespace rtpro
