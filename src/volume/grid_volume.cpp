#include "rtpro/volume/grid_volume.h"

namespace rtpro {

namespace {

PlacedGrid place(VoxelGrid grid, const Affine& medium_to_world, const SourceLocation& where, const char* role) {
  const Affine index_to_world = compose(medium_to_world, grid.index_to_medium);
  const std::optional<Affine> world_to_index = inverse(index_to_world);
  if (!world_to_index || !index_to_world.is_finite())
    throw InputError(where, std::string("the volume's ") + role +
                                " grid, placed by the entry's transform, has a singular or non-finite transform");
  return {std::move(grid), *world_to_index};
}

// The bricks' values summed over the box's voxels (the background's weight left out: a fog
// volume's is 0).
float mean_over_box(const VoxelGrid& grid, const BBox& box) {
  if (box.empty()) return 0.0f;
  double sum = 0.0;
  grid.for_each_brick([&](const VoxelCoord&, std::span<const float> values) {
    for (const float v : values) sum += v;
  });
  const Vec3 extent = box.extent();
  const double voxels = double(extent.x) * double(extent.y) * double(extent.z);
  return voxels > 0.0 ? static_cast<float>(sum / voxels) : 0.0f;
}

}  // namespace

GridVolume place_grid_volume(VdbGrids grids, const Affine& medium_to_world, const SourceLocation& where) {
  GridVolume volume;
  volume.density_to_world = compose(medium_to_world, grids.density.index_to_medium);
  volume.density = place(std::move(grids.density), medium_to_world, where, "density");
  if (grids.emission) volume.emission = place(std::move(*grids.emission), medium_to_world, where, "emission");
  if (grids.temperature)
    volume.temperature = place(std::move(*grids.temperature), medium_to_world, where, "temperature");
  volume.majorants = MajorantGrid(volume.density.grid);
  volume.mean_density = mean_over_box(volume.density.grid, volume.majorants.bounds());
  volume.memory = grids.memory;
  volume.memory.bytes += volume.majorants.memory_bytes();
  return volume;
}

}  // namespace rtpro
