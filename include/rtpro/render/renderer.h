#pragma once
// Tiled, progressive parallel rendering with oneTBB: workers take work items (a tile in a pass)
// from a TileSource, render them and hand them to a TileSink. render_image renders the region in
// passes (pass_schedule.h) into a ProgressiveFilm and resolves it into one image; a pixel's value
// depends only on the scene, the settings, the seed and the passes it took, never on threads,
// tiles, the region, ranks, resumes or the order items are rendered in.
#include "rtpro/backend/backend.h"
#include "rtpro/image/image.h"
#include "rtpro/render/adaptive_sampling.h"
#include "rtpro/render/film.h"
#include "rtpro/render/progressive_film.h"
#include "rtpro/render/render_observer.h"
#include "rtpro/render/tile_executor.h"
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

struct RenderOptions {
  int tile_size = 32;
  std::optional<PixelRegion> region;  // default: the whole image
  std::vector<Aov> aovs;
  const std::atomic<bool>* cancel = nullptr;  // checked before each tile starts
  // After the first pass, the render stops at this many seconds from its start (0: no limit),
  // with the image of the passes finished by then.
  double time_limit_seconds = 0.0;
  // Threshold 0: every pixel takes every pass. Else passes stop for pixels that converged, and the
  // render when all have. Not with a tile_executor (another process has no film to decide from).
  AdaptiveSampling adaptive;
  // Told of each finished work item, merged pass and preview image (render_observer.h), in order.
  std::vector<RenderObserver*> observers;
  // Work items of this grid rendered before (read back from a resume journal, cumulative ones
  // first): they go into the film as they are and only the other items are rendered. Items that
  // do not fit together (cumulative items of different passes, or not of every tile) are all
  // ignored.
  std::span<const TileResult> journal_items;
  // Renders the work items (tile_executor.h); none: this process's workers, one pass at a time.
  TileExecutor* tile_executor = nullptr;
  // The scene's image textures, opened (open_textures); required when it has any.
  const TextureLookup* textures = nullptr;
  // The scene's environment, built from its image; required when it has one.
  const EnvironmentLight* environment = nullptr;
  // Called once no more rays will be traced, before the film is resolved into the image: the
  // caller may free the backend then, so that its bytes and the image's are never resident at once.
  std::function<void()> tracing_done;
};

// Why a render stopped: every pass done, every pixel converged, the time limit, or an interrupt.
enum class RenderStop { kAllPasses, kConverged, kTimeLimit, kInterrupted };

struct RenderResult {
  // Full camera resolution; pixels outside the region are 0. The passes merged, or when none
  // was, the tiles of the first pass that finished (the others 0).
  Image image;
  RayCounts rays;
  std::uint64_t nan_samples = 0;  // samples that came out NaN/inf and were counted as black
  std::size_t tiles_done = 0;     // work items (tiles in passes), journal's included
  std::size_t tiles_total = 0;
  int passes_done = 0;
  int passes_total = 0;
  RenderStop stop = RenderStop::kAllPasses;
  SampleCounts samples;  // as the image shows them
  // Of each pass merged here: seconds from the previous pass's merge (the first: from the start).
  std::vector<double> pass_seconds;
  double seconds = 0.0;
  bool complete() const { return stop != RenderStop::kInterrupted; }
};

// Throws InputError for a region outside the image or a tile size below 1.
PixelRegion checked_region(const RenderScene& scene, const RenderOptions& options);

// The per-pixel sums the render's work items carry: what its layers and adaptive sampling read.
SumLayout render_sums(const RenderOptions& options);

RenderResult render_image(const RenderScene& scene, const Backend& backend, const RenderOptions& options);

}  // namespace rtpro
