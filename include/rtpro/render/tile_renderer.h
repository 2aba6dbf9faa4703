#pragma once
// Renders one work item (a tile in a pass, tiles.h): generates the pass's camera samples of each
// pixel that takes part, traces them in batches of whole pixels with the scene's integrator
// (render/integrators/) and sums each pixel's samples, in sample order,
// into the item's sums (pixel_sums.h).
#include "rtpro/backend/backend.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/render/film.h"
#include "rtpro/render/pass_schedule.h"
#include "rtpro/render/sample_result.h"
#include "rtpro/render/sampler.h"
#include "rtpro/render/tiles.h"
#include "rtpro/scene/render_scene.h"

#include <memory>
#include <vector>

namespace rtpro {

class TileRenderer {
 public:
  // The buffers one worker thread reuses from tile to tile.
  struct Workspace {
    Workspace();
    ~Workspace();
    Workspace(Workspace&&) noexcept;
    Workspace& operator=(Workspace&&) noexcept;
    std::vector<Ray> camera_rays;
    std::vector<SampleKey> sample_keys;
    std::vector<std::uint64_t> pixel_keys;   // every listed pixel's, y · width + x
    std::vector<PixelOffset> pixel_offsets;  // every camera sample's, drawn in one batch
    std::vector<float> film_x, film_y;       // every pinhole camera sample's film point
    std::vector<float> camera_times;         // every camera sample's time, while the shutter is open
    std::vector<SampleResult> samples;
    // A pixel of the tile that takes part in the pass: its place among the tile's sums
    // (row-major) and its image coordinates, kept beside it rather than divided out per sample.
    struct TilePixel {
      std::uint32_t index;
      int x, y;
    };
    std::vector<TilePixel> pixels;
    struct IntegratorBuffers;  // the integrators' own (render/integrators/integrator.h)
    std::unique_ptr<IntegratorBuffers> integrator;
  };

  // `grid`: the render's work items, with the passes of render_passes(scene).
  // `sums`: the per-pixel sums the items carry.
  // `textures`: the scene's image textures, opened (open_textures); required when it has any.
  // `environment`: the scene's environment, built from its image; required when it has one.
  TileRenderer(const RenderScene& scene, const Backend& backend, const TileGrid& grid, const SumLayout& sums,
               const TextureLookup* textures = nullptr, const EnvironmentLight* environment = nullptr);
  ~TileRenderer();

  // Work item `index` of the grid, whose tile is `tile`.
  TileResult render(std::size_t index, const PixelRegion& tile, Workspace& workspace) const;

  // Pixels of the grid's region (row-major, 1: takes part) that the passes rendered from now on
  // sample; null (the default) for all. The mask must not change while a pass renders.
  void set_active_pixels(const std::vector<std::uint8_t>* mask) { active_ = mask; }

  const PassSchedule& schedule() const { return schedule_; }
  const TileGrid& grid() const { return grid_; }
  const SumLayout& sums() const { return sums_; }

 private:
  void render_pixels(SampleRange samples, const Workspace::TilePixel* pixels, std::size_t count, TileResult& out,
                     Workspace& ws) const;

  const RenderScene& scene_;
  const Backend& backend_;
  TileGrid grid_;
  SumLayout sums_;
  PassSchedule schedule_;
  const std::vector<std::uint8_t>* active_ = nullptr;
  struct Integration;  // the samplers and the scene's integrator (tile_renderer.cpp)
  std::unique_ptr<const Integration> integration_;
};

// The pass schedule of a scene's render settings, and the grid of its work items.
PassSchedule render_passes(const RenderScene& scene);
TileGrid render_grid(const RenderScene& scene, const PixelRegion& region, int tile_size);

}  // namespace rtpro
