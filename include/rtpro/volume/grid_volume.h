#pragma once
// A grid medium's data placed in the scene (pbrt-v4's GridMedium without its optical
// parameters): the density grid with its majorant grid, the optional emission and temperature
// grids, and the transforms from the world to each grid's index space. The medium kind that
// renders it multiplies density by its σ_t (density_scale × (σ_a + σ_s)).
#include "rtpro/core/bbox.h"
#include "rtpro/core/error.h"
#include "rtpro/core/ray.h"
#include "rtpro/core/transform.h"
#include "rtpro/volume/majorant_grid.h"
#include "rtpro/volume/majorant_iterator.h"
#include "rtpro/volume/vdb_file.h"
#include "rtpro/volume/voxel_grid.h"

#include <optional>

namespace rtpro {

// A grid and the map from world space to its index space.
struct PlacedGrid {
  VoxelGrid grid;
  Affine world_to_index;
  // The trilinear value at a world point; 0 outside the grid's support.
  float at(const Vec3& world) const {
    const Vec3 p = world_to_index.apply_point(world);
    const BBox& box = grid.support();
    if (!(p.x > box.lower.x && p.y > box.lower.y && p.z > box.lower.z && p.x < box.upper.x && p.y < box.upper.y &&
          p.z < box.upper.z))
      return 0.0f;
    return grid.lookup(p);
  }
};

struct GridVolume {
  PlacedGrid density;
  std::optional<PlacedGrid> emission, temperature;
  MajorantGrid majorants;  // over density's index space
  Affine density_to_world;
  VolumeMemory memory;
  // The density averaged over the majorant grid's box (index space): what a renderer that cannot
  // track the grid (Whitted) shows of it as a uniform absorption.
  float mean_density = 0.0f;

  // The world box the density can be non-zero in (the support's corners transformed).
  BBox world_bounds() const { return density_to_world.apply(majorants.bounds()); }
  // Segments of the ray (world space, t in [ray.tnear, t_max]) with σ_maj = sigma_t × the
  // density's majorant: the grid kind's `majorants` of render/media/medium_interface.h.
  DdaMajorantIterator majorants_along(const Ray& ray, float t_max, float sigma_t, bool skip_empty = false) const {
    return {density.world_to_index.apply_point(ray.org),
            density.world_to_index.apply_vector(ray.dir),
            ray.tnear,
            t_max,
            majorants,
            sigma_t,
            skip_empty};
  }
};

// Places the grids read from a file by `medium_to_world` (the scene's transform of the volume;
// each grid's own index-to-medium transform is applied first) and builds the majorant grid.
// Throws InputError at `where` when the transform cannot be inverted.
GridVolume place_grid_volume(VdbGrids grids, const Affine& medium_to_world, const SourceLocation& where);

}  // namespace rtpro
