#include "rtpro/render/renderer.h"

#include "rtpro/core/error.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/render/camera.h"
#include "rtpro/render/sampler.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <memory>
#include <span>
#include <cmath>

namespace rtpro {

namespace {

struct TileStats {
  RayCounts rays;
  std::uint64_t nan_samples = 0;
};

// Camera rays of one tile row, traced as one batch (Embree streams them coherently).
struct RowBatch {
  std::vector<Ray> rays;
  std::vector<Hit> hits;
  std::unique_ptr<bool[]> found;
  explicit RowBatch(std::size_t capacity) : rays(capacity), hits(capacity), found(new bool[capacity]) {}
};

void render_tile(const RenderScene& scene, const Backend& backend, const Camera& camera,
                 const StratifiedSampler& sampler, const PixelRegion& tile, Film& film, TileStats& stats) {
  const int spp = sampler.samples_per_pixel();
  const int width = scene.camera.width;
  const std::size_t row_rays = static_cast<std::size_t>(tile.width()) * spp;
  RowBatch batch(row_rays);
  for (int y = tile.y0; y < tile.y1; ++y) {
    std::size_t i = 0;
    for (int x = tile.x0; x < tile.x1; ++x) {
      const std::uint64_t pixel_key = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(width) + x;
      for (int s = 0; s < spp; ++s, ++i) {
        const PixelOffset offset = sampler.sample(pixel_key, s);
        batch.rays[i] = camera.generate(static_cast<float>(x) + offset.x, static_cast<float>(y) + offset.y);
      }
    }
    backend.intersect(std::span<const Ray>(batch.rays.data(), row_rays), std::span<Hit>(batch.hits.data(), row_rays),
                      std::span<bool>(batch.found.get(), row_rays));
    i = 0;
    for (int x = tile.x0; x < tile.x1; ++x) {
      PixelAccumulator acc;
      for (int s = 0; s < spp; ++s, ++i) {
        PrimaryHit primary;
        Color radiance = trace_radiance_from(scene, backend, batch.rays[i], batch.found[i], batch.hits[i], stats.rays,
                                             &primary);
        if (!is_finite(radiance)) {
          ++stats.nan_samples;
          radiance = Color(0.0f);
        }
        acc.add(radiance, primary);
      }
      film.set_pixel(x, y, acc, spp);
    }
  }
}

std::vector<PixelRegion> make_tiles(const PixelRegion& region, int tile_size) {
  std::vector<PixelRegion> tiles;
  for (int y = region.y0; y < region.y1; y += tile_size)
    for (int x = region.x0; x < region.x1; x += tile_size)
      tiles.push_back({x, y, std::min(x + tile_size, region.x1), std::min(y + tile_size, region.y1)});
  return tiles;
}

}  // namespace

RenderResult render_image(const RenderScene& scene, const Backend& backend, const RenderOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const int width = scene.camera.width, height = scene.camera.height;
  const PixelRegion region = options.region.value_or(PixelRegion{0, 0, width, height});
  if (region.x0 < 0 || region.y0 < 0 || region.x1 > width || region.y1 > height || region.width() <= 0 ||
      region.height() <= 0)
    throw InputError("region " + std::to_string(region.x0) + "," + std::to_string(region.y0) + "," +
                     std::to_string(region.x1) + "," + std::to_string(region.y1) + " is empty or outside the " +
                     std::to_string(width) + "x" + std::to_string(height) + " image");
  if (options.tile_size <= 0) throw InputError("tile size must be positive");

  const Camera camera(scene.camera, width, height);
  const StratifiedSampler sampler(scene.render.spp, scene.render.seed);
  Film film(width, height, options.aovs);
  const std::vector<PixelRegion> tiles = make_tiles(region, options.tile_size);
  std::vector<TileStats> tile_stats(tiles.size());
  std::vector<char> tile_done(tiles.size(), 0);
  std::atomic<std::size_t> done{0};

  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
    set_tracing_fp_mode();
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return;
      render_tile(scene, backend, camera, sampler, tiles[i], film, tile_stats[i]);
      tile_done[i] = 1;
      const std::size_t finished = done.fetch_add(1) + 1;
      if (options.on_tile_done) options.on_tile_done(finished, tiles.size());
    }
  });

  RenderResult result;
  result.tiles_total = tiles.size();
  // Summed in tile order so the totals never depend on scheduling.
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    if (!tile_done[i]) continue;
    ++result.tiles_done;
    result.rays += tile_stats[i].rays;
    result.nan_samples += tile_stats[i].nan_samples;
  }
  result.image = std::move(film.image());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace rtpro
