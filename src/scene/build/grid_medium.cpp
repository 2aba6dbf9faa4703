#include "rtpro/scene/grid_medium.h"

#include "rtpro/core/printable_text.h"

namespace rtpro {

namespace {

VdbRequest request_of(const VolumeDesc& desc) {
  VdbRequest request;
  request.file = desc.file;
  request.where = desc.where;
  request.density = desc.grid;
  request.emission = desc.emission_grid;
  request.temperature = desc.temperature_grid;
  return request;
}

}  // namespace

GridMedium make_grid_medium(const VolumeDesc& desc) {
  GridMedium medium;
  medium.grid = std::make_shared<const GridVolume>(
      place_grid_volume(read_vdb_grids(request_of(desc)), desc.transform, desc.where));
  // albedo = σs/σt with σt = density_scale per unit of density.
  medium.sigma_s = desc.albedo * desc.density_scale;
  medium.sigma_a = (Color(1.0f) - desc.albedo) * desc.density_scale;
  medium.anisotropy = desc.anisotropy;
  medium.emission = desc.emission * desc.emission_scale;
  medium.temperature_scale = desc.temperature_scale;
  medium.file = printable_text(desc.file.string());
  medium.grid_name = printable_text(desc.grid);
  return medium;
}

std::uint64_t estimate_grid_medium_bytes(const VolumeDesc& desc) { return estimate_vdb_bytes(request_of(desc)); }

}  // namespace rtpro
