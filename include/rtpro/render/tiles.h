#pragma once
// Work is handed out and collected in tiles. A TileGrid numbers the tiles of a region once and for
// all; a TileSource says which tile a worker renders next and a TileSink takes each finished tile.
// The TBB renderer, a distributed scheduler (tiles from another rank, finished tiles sent back)
// and a resume journal (skip tiles already done, record each as it finishes) are all a source and a
// sink: the renderer itself only renders the tile it is given. A tile's pixels depend on nothing
// but the scene, the settings, the seed and the tile's own region.
#include "rtpro/render/ray_counts.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace rtpro {

// Half-open pixel window [x0, x1) × [y0, y1).
struct PixelRegion {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  std::size_t pixel_count() const { return static_cast<std::size_t>(width()) * static_cast<std::size_t>(height()); }
};

// Row-major tiles of `tile_size` pixels covering `region`; the last row and column may be smaller.
// A tile size beyond the region's larger side is clamped to it (one tile either way), and
// tile_size() is the clamped size.
//
// A render proceeds in passes (pass_schedule.h), each adding samples to every tile, so the unit of
// work is a tile in a pass: work item i is tile i mod tiles_per_pass() of pass i div
// tiles_per_pass(), and count() numbers every item of every pass.
class TileGrid {
 public:
  TileGrid(const PixelRegion& region, int tile_size, int passes = 1);
  std::size_t count() const { return tiles_per_pass() * static_cast<std::size_t>(passes_); }
  std::size_t tiles_per_pass() const { return columns_ * rows_; }
  int passes() const { return passes_; }
  // The region of work item `index`'s tile, and its pass.
  PixelRegion tile(std::size_t index) const;
  int pass(std::size_t index) const { return static_cast<int>(index / tiles_per_pass()); }
  const PixelRegion& region() const { return region_; }
  int tile_size() const { return tile_size_; }

 private:
  PixelRegion region_;
  int tile_size_;
  std::size_t columns_, rows_;
  int passes_;
};

// A rendered work item: its tile's per-pixel sample sums of one pass (row-major, SumLayout::floats()
// a pixel: pixel_sums.h) and what it cost. A
// `cumulative` item holds instead the sums of every pass up to and including its own (a resume
// journal keeps those in place of the passes they sum).
struct TileResult {
  std::size_t index = 0;
  PixelRegion region;
  std::vector<float> pixels;
  RayCounts rays;
  std::uint64_t nan_samples = 0;  // samples that came out NaN/inf and were counted as black
  bool cumulative = false;
};

// Called concurrently by the render workers.
class TileSource {
 public:
  virtual ~TileSource() = default;
  // The next tile index to render, or nothing when the worker should stop.
  virtual std::optional<std::size_t> next() = 0;
  // How many more tiles next() would return, when the source knows: a distributed scheduler
  // hands out smaller batches as the pool drains, so that no rank is left holding the tail.
  virtual std::optional<std::size_t> remaining() const { return std::nullopt; }
};

class TileSink {
 public:
  virtual ~TileSink() = default;
  virtual void put(TileResult&& tile) = 0;
};

// Every tile of a grid once, in index order; stops early when `cancel` becomes true.
class AllTilesSource final : public TileSource {
 public:
  explicit AllTilesSource(std::size_t count, const std::atomic<bool>* cancel = nullptr)
      : count_(count), cancel_(cancel) {}
  std::optional<std::size_t> next() override;
  std::optional<std::size_t> remaining() const override { return count_ - std::min(next_.load(), count_); }

 private:
  std::size_t count_;
  const std::atomic<bool>* cancel_;
  std::atomic<std::size_t> next_{0};
};

// The listed tiles once each, in the order given; stops early when `cancel` becomes true.
class TileListSource final : public TileSource {
 public:
  explicit TileListSource(std::vector<std::size_t> indices, const std::atomic<bool>* cancel = nullptr)
      : indices_(std::move(indices)), cancel_(cancel) {}
  std::optional<std::size_t> next() override;
  std::optional<std::size_t> remaining() const override {
    return indices_.size() - std::min(next_.load(), indices_.size());
  }

 private:
  std::vector<std::size_t> indices_;
  const std::atomic<bool>* cancel_;
  std::atomic<std::size_t> next_{0};
};

}  // namespace rtpro
