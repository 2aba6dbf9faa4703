#pragma once
// Renders one work item (a tile in a pass, tiles.h): generates the pass's camera samples of each
// pixel that takes part, shades them in batches of whole pixels with the scene's integrator
// (whitted: shading.h; path: path_integrator.h) and sums each pixel's samples, in sample order,
// into the item's sums (pixel_sums.h).
#include "rtpro/backend/backend.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/render/film.h"
#include "rtpro/render/light_set.h"
#include "rtpro/render/pass_schedule.h"
#include "rtpro/render/path_integrator.h"
#include "rtpro/render/sampler.h"
#include "rtpro/render/shading.h"
#include "rtpro/render/tiles.h"
#include "rtpro/scene/render_scene.h"

#include <optional>
#include <vector>

namespace rtpro {

class TileRenderer {
 public:
  // The buffers one worker thread reuses from tile to tile.
  struct Workspace {
    std::vector<Ray> camera_rays;
    std::vector<SampleKey> sample_keys;
    std::vector<PixelOffset> pixel_offsets;  // one pixel's, spp of them
    std::vector<PixelOffset> sobol_offsets;  // every camera sample's, drawn in one batch
    std::vector<SampleResult> samples;
    std::vector<std::uint32_t> pixels;  // the tile's pixels that take part in the pass
    ShadingWorkspace shading;
    PathWorkspace paths;
  };

  // `grid`: the render's work items, with the passes of render_passes(scene).
  // `sums`: the per-pixel sums the items carry.
  // `textures`: the scene's image textures, opened (open_textures); required when it has any.
  // `environment`: the scene's environment, built from its image; required when it has one.
  TileRenderer(const RenderScene& scene, const Backend& backend, const TileGrid& grid, const SumLayout& sums,
               const TextureLookup* textures = nullptr, const EnvironmentLight* environment = nullptr);

  // Work item `index` of the grid, whose tile is `tile`.
  TileResult render(std::size_t index, const PixelRegion& tile, Workspace& workspace) const;

  // Pixels of the grid's region (row-major, 1: takes part) that the passes rendered from now on
  // sample; null (the default) for all. The mask must not change while a pass renders.
  void set_active_pixels(const std::vector<std::uint8_t>* mask) { active_ = mask; }

  const PassSchedule& schedule() const { return schedule_; }
  const TileGrid& grid() const { return grid_; }
  const SumLayout& sums() const { return sums_; }

 private:
  void render_pixels(const PixelRegion& tile, SampleRange samples, const std::uint32_t* pixels, std::size_t count,
                     TileResult& out, Workspace& ws) const;

  const RenderScene& scene_;
  const Backend& backend_;
  TileGrid grid_;
  SumLayout sums_;
  PassSchedule schedule_;
  const std::vector<std::uint8_t>* active_ = nullptr;
  const TextureLookup* textures_;
  const EnvironmentLight* environment_;
  StratifiedSampler sampler_;
  SobolSampler sobol_;
  std::optional<LightSet> path_lights_;  // built for the path integrator only
};

// The pass schedule of a scene's render settings, and the grid of its work items.
PassSchedule render_passes(const RenderScene& scene);
TileGrid render_grid(const RenderScene& scene, const PixelRegion& region, int tile_size);

}  // namespace rtpro
