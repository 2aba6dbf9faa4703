#include "rtpro/render/renderer.h"

#include "rtpro/core/error.h"
#include "rtpro/core/fp_env.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <stdexcept>
#include <string>

namespace rtpro {

void render_tiles(const TileRenderer& renderer, const TileGrid& grid, TileSource& source, TileSink& sink) {
  // One long-lived task per worker, each pulling tiles until the source runs dry: the source, not
  // TBB's partitioner, decides the order, which is what a distributed scheduler needs.
  const int workers = tbb::this_task_arena::max_concurrency();
  tbb::parallel_for(tbb::blocked_range<int>(0, workers, 1), [&](const tbb::blocked_range<int>& slots) {
    set_tracing_fp_mode();
    TileRenderer::Workspace workspace;
    for (int slot = slots.begin(); slot != slots.end(); ++slot)
      while (const std::optional<std::size_t> index = source.next())
        sink.put(renderer.render(*index, grid.tile(*index), workspace));
  });
}

ImageTileSink::ImageTileSink(Image& image, std::size_t tile_count) : image_(image), stats_(tile_count) {}

void ImageTileSink::put(TileResult&& tile) {
  if (on_tile_result) on_tile_result(tile);
  const auto channels = static_cast<std::size_t>(image_.channel_count());
  const auto row_floats = static_cast<std::size_t>(tile.region.width()) * channels;
  for (int y = tile.region.y0; y < tile.region.y1; ++y) {
    const float* from = tile.pixels.data() + static_cast<std::size_t>(y - tile.region.y0) * row_floats;
    std::copy(from, from + row_floats, &image_.at(tile.region.x0, y, 0));
  }
  stats_[tile.index] = {true, tile.rays, tile.nan_samples};
  if (on_tile_pixels) on_tile_pixels(tile.region);
  const std::size_t done = done_.fetch_add(1) + 1;
  if (on_tile_done) on_tile_done(done);
}

std::size_t ImageTileSink::tiles_done() const { return done_.load(); }

RayCounts ImageTileSink::rays() const {
  RayCounts total;
  for (const TileStats& s : stats_)
    if (s.done) total += s.rays;
  return total;
}

std::uint64_t ImageTileSink::nan_samples() const {
  std::uint64_t total = 0;
  for (const TileStats& s : stats_)
    if (s.done) total += s.nan_samples;
  return total;
}

PixelRegion checked_region(const RenderScene& scene, const RenderOptions& options) {
  const int width = scene.camera.width, height = scene.camera.height;
  const PixelRegion region = options.region.value_or(PixelRegion{0, 0, width, height});
  if (region.x0 < 0 || region.y0 < 0 || region.x1 > width || region.y1 > height || region.width() <= 0 ||
      region.height() <= 0)
    throw InputError("region " + std::to_string(region.x0) + "," + std::to_string(region.y0) + "," +
                     std::to_string(region.x1) + "," + std::to_string(region.y1) + " is empty or outside the " +
                     std::to_string(width) + "x" + std::to_string(height) + " image");
  if (options.tile_size <= 0) throw InputError("tile size must be positive");
  return region;
}

RenderResult render_image(const RenderScene& scene, const Backend& backend, const RenderOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const TileGrid grid(checked_region(scene, options), options.tile_size);
  const FilmLayout layout(options.aovs);
  const TileRenderer renderer(scene, backend, layout, options.textures, options.environment);

  RenderResult result;
  result.image = Image(scene.camera.width, scene.camera.height, layout.channels());
  result.tiles_total = grid.count();
  ImageTileSink sink(result.image, grid.count());
  if (options.on_tile_done)
    sink.on_tile_done = [&](std::size_t done) { options.on_tile_done(done, grid.count()); };
  if (options.on_tile_pixels)
    sink.on_tile_pixels = [&](const PixelRegion& region) { options.on_tile_pixels(result.image, region); };
  std::vector<bool> finished(grid.count(), false);
  for (const TileResult& tile : options.finished_tiles) {
    if (tile.index >= grid.count() || finished[tile.index] || tile.region.x0 != grid.tile(tile.index).x0 ||
        tile.region.y0 != grid.tile(tile.index).y0)
      throw std::logic_error("render_image: a finished tile is not a tile of this grid, or is given twice");
    finished[tile.index] = true;
    sink.put(TileResult(tile));
  }
  std::vector<std::size_t> remaining;
  for (std::size_t index = 0; index < grid.count(); ++index)
    if (!finished[index]) remaining.push_back(index);
  TileListSource source(std::move(remaining), options.cancel);
  sink.on_tile_result = options.on_tile_result;
  if (options.tile_executor)
    options.tile_executor(renderer, grid, source, sink);
  else
    render_tiles(renderer, grid, source, sink);

  result.tiles_done = sink.tiles_done();
  result.rays = sink.rays();
  result.nan_samples = sink.nan_samples();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace rtpro
