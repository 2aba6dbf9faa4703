#pragma once
// Tiled parallel rendering with oneTBB. Each tile writes its own pixels once; a pixel's value
// depends only on the scene, the settings and the seed, never on threads, tiles or the region.
#include "rtpro/backend/backend.h"
#include "rtpro/image/image.h"
#include "rtpro/render/film.h"
#include "rtpro/render/shading.h"
#include "rtpro/scene/render_scene.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace rtpro {

// Half-open pixel window [x0, x1) × [y0, y1).
struct PixelRegion {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

struct RenderOptions {
  int tile_size = 32;
  std::optional<PixelRegion> region;  // default: the whole image
  std::vector<Aov> aovs;
  const std::atomic<bool>* cancel = nullptr;  // checked before each tile starts
  // Called after each finished tile (from worker threads) with tiles done and total.
  std::function<void(std::size_t, std::size_t)> on_tile_done;
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

RenderResult render_image(const RenderScene& scene, const Backend& backend, const RenderOptions& options);

}  // namespace rtpro
