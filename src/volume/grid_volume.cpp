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

}  // namespace

GridVolume place_grid_volume(VdbGrids grids, const Affine& medium_to_world, const SourceLocation& where) {
  GridVolume volume;
  volume.density_to_world = compose(medium_to_world, grids.density.index_to_medium);
  volume.density = place(std::move(grids.density), medium_to_world, where, "density");
  if (grids.emission) volume.emission = place(std::move(*grids.emission), medium_to_world, where, "emission");
  if (grids.temperature)
    volume.temperature = place(std::move(*grids.temperature), medium_to_world, where, "temperature");
  volume.majorants = MajorantGrid(volume.density.grid);
  volume.memory = grids.memory;
  volume.memory.bytes += volume.majorants.memory_bytes();
  return volume;
}

}  // namespace rtpro
