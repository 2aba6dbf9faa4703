#pragma once
// Tiled parallel rendering with oneTBB: workers take tiles from a TileSource, render them and hand
// them to a TileSink. render_image is the single-process composition (every tile of the region,
// into one image); a pixel's value depends only on the scene, the settings and the seed, never on
// threads, tiles, the region or the order tiles are rendered in.
#include "rtpro/backend/backend.h"
#include "rtpro/image/image.h"
#include "rtpro/render/film.h"
#include "rtpro/render/shading.h"
#include "rtpro/render/tile_renderer.h"
#include "rtpro/render/tiles.h"
#include "rtpro/scene/render_scene.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace rtpro {

// Workers pull tiles from `source` until it has none, render each and give it to `sink`.
void render_tiles(const TileRenderer& renderer, const TileGrid& grid, TileSource& source, TileSink& sink);

// Copies finished tiles into a full-size image and keeps each tile's statistics, so totals can be
// summed in tile order whatever order tiles finished in.
class ImageTileSink final : public TileSink {
 public:
  ImageTileSink(Image& image, std::size_t tile_count);
  void put(TileResult&& tile) override;

  // Called after each tile lands (from worker threads) with tiles done so far.
  std::function<void(std::size_t)> on_tile_done;
  // Called after each tile's pixels are in the image, before on_tile_done, with its region.
  std::function<void(const PixelRegion&)> on_tile_pixels;
  // Called with each tile before it lands, e.g. to record it in a resume journal.
  std::function<void(const TileResult&)> on_tile_result;

  std::size_t tiles_done() const;
  RayCounts rays() const;
  std::uint64_t nan_samples() const;

 private:
  struct TileStats {
    bool done = false;
    RayCounts rays;
    std::uint64_t nan_samples = 0;
  };
  Image& image_;
  std::vector<TileStats> stats_;
  std::atomic<std::size_t> done_{0};
};

struct RenderOptions {
  int tile_size = 32;
  std::optional<PixelRegion> region;  // default: the whole image
  std::vector<Aov> aovs;
  const std::atomic<bool>* cancel = nullptr;  // checked before each tile starts
  // Called after each finished tile (from worker threads) with tiles done and total.
  std::function<void(std::size_t, std::size_t)> on_tile_done;
  // Called after each finished tile (from worker threads) with the image being rendered and the
  // tile's region, whose pixels are final there: live previews read them.
  std::function<void(const Image&, const PixelRegion&)> on_tile_pixels;
  // Tiles of this grid rendered before (read back from a resume journal): they land in the image
  // as they are and only the other tiles are rendered.
  std::span<const TileResult> finished_tiles;
  // Called (from worker threads) with each newly rendered tile before it lands in the image.
  std::function<void(const TileResult&)> on_tile_result;
  // Renders the tiles `source` hands out into `sink`; unset, this process's workers do
  // (render_tiles). A distributed render shares them with other processes.
  std::function<void(const TileRenderer&, const TileGrid&, TileSource&, TileSink&)> tile_executor;
  // The scene's image textures, opened (open_textures); required when it has any.
  const TextureLookup* textures = nullptr;
  // The scene's environment, built from its image; required when it has one.
  const EnvironmentLight* environment = nullptr;
};

struct RenderResult {
  Image image;  // full camera resolution; pixels outside the region (or unfinished) are 0
  RayCounts rays;
  std::uint64_t nan_samples = 0;  // samples that came out NaN/inf and were counted as black
  std::size_t tiles_done = 0;
  std::size_t tiles_total = 0;
  double seconds = 0.0;
  bool complete() const { return tiles_done == tiles_total; }
};

// Throws InputError for a region outside the image or a tile size below 1.
PixelRegion checked_region(const RenderScene& scene, const RenderOptions& options);

RenderResult render_image(const RenderScene& scene, const Backend& backend, const RenderOptions& options);

}  // namespace rtpro
