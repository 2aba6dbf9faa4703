#pragma once
// The sums of every pixel of a render's region over the passes merged so far. Work items (a tile in
// a pass, tiles.h) arrive in any order from any thread or rank; a pass is merged into the sums
// only when all its tiles are in and every earlier pass is merged, tile by tile in parallel, so a
// pixel's sums are added in pass order whatever the arrival order, and the sums always hold whole
// passes: what an interrupt or a time limit shows. The first pass is the exception that costs
// nothing: it adds to sums of nothing, so its tiles are set as they come.
#include "rtpro/core/huge_page_buffer.h"
#include "rtpro/image/image.h"
#include "rtpro/render/film.h"
#include "rtpro/render/tiles.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <vector>

namespace rtpro {

// The samples the pixels of a region took: all `spp` for a finished render; fewer for one
// stopped by its time limit; anything up to `spp` under adaptive sampling.
struct SampleCounts {
  int min = 0, max = 0;
  double mean = 0.0;
  bool uniform() const { return min == max; }
};

class ProgressiveFilm {
 public:
  ProgressiveFilm(const TileGrid& grid, const SumLayout& sums);

  // Takes a work item of the grid (any thread). A cumulative item sets its tile's sums (a resume
  // journal's); all tiles' cumulative items must be of one pass and come before any other item.
  // Merges every pass this completes, calling on_pass_merged(pass) after each.
  void add(TileResult&& item);
  std::function<void(int)> on_pass_merged;

  int passes_merged() const;
  // Whether work item `index` is in: merged or waiting for the items of its pass or of earlier ones.
  bool has(std::size_t index) const;

  const TileGrid& grid() const { return grid_; }
  const SumLayout& sums() const { return sums_; }
  // A pixel's sums through the last merged pass (the sums its layout does not keep are 0).
  PixelAccumulator pixel(int x, int y) const { return sums_.load(pixel_sums(x, y)); }
  // Writes the region's pixels into `image` (full camera size, layout's channels), and gives the
  // samples its pixels' sums hold (read while their rows are in the cache, not in a pass of its own
  // over the film: that pass cost a 1-spp 1024² frame 2.7 ms).
  SampleCounts resolve(const FilmLayout& layout, Image& image) const;
  // The same, with each tile of the first unmerged pass that is in shown with it (what an
  // interrupted single-pass render has to show); the counts are of the merged passes.
  SampleCounts resolve_with_partial_pass(const FilmLayout& layout, Image& image) const;

  // Every tile's sums through the last merged pass, as cumulative items (before the first pass is
  // whole: the first pass's tiles that are in, as items of that pass), and the items waiting: all a
  // resume journal has to keep. Handed to `visit` one at a time, in one item refilled for each, so
  // that writing a journal never holds a second copy of the film. Call it where no pass merges
  // meanwhile: from on_pass_merged, or once the tiles are rendered.
  void visit_journal_items(const std::function<void(const TileResult&)>& visit) const;
  // Bytes of the sums (a journal holding more than a few times this is worth compacting).
  std::size_t bytes() const { return pixels_.size() * sizeof(float); }

  RayCounts rays() const;
  std::uint64_t nan_samples() const;
  std::size_t items_in() const;

 private:
  struct WaitingPass {
    std::vector<TileResult> items;  // by tile; an absent item has no pixels
    std::size_t count = 0;
  };
  // Adds the item's sums to the tile's, or sets them (`set`: a cumulative item, or a first-pass
  // tile onto sums still zero); the caller owns the item's pixels.
  void merge_pixels(const TileResult& item, bool set);
  void count_cost(const TileResult& item);  // under the lock
  std::size_t sums_offset(int x, int y) const {
    const PixelRegion& region = grid_.region();
    return (static_cast<std::size_t>(y - region.y0) * static_cast<std::size_t>(region.width()) +
            static_cast<std::size_t>(x - region.x0)) *
           static_cast<std::size_t>(sums_.floats());
  }
  const float* pixel_sums(int x, int y) const { return pixels_.get() + sums_offset(x, y); }
  void merge_ready_passes(std::unique_lock<std::mutex>& lock);

  TileGrid grid_;
  SumLayout sums_;
  // sums_.floats() a pixel, row-major; zero as mapped, and populated before any tile is in (the
  // vector's zeroing was a second pass over it in one thread).
  HugePageBuffer<float> pixels_;
  mutable std::mutex mutex_;
  std::map<int, WaitingPass> waiting_;
  int merged_ = 0;
  bool merging_ = false;
  // The first pass's tiles, merged as they come.
  enum : std::uint8_t { kTileAbsent, kTileMerging, kTileMerged };
  std::vector<std::uint8_t> first_pass_tiles_;
  std::size_t first_pass_in_ = 0, first_pass_merged_ = 0;
  std::size_t cumulative_tiles_ = 0;
  int cumulative_pass_ = 0;
  // Of the merged passes, by tile: what the sums cost.
  std::vector<RayCounts> tile_rays_;
  std::vector<std::uint64_t> tile_nan_samples_;
  std::size_t items_in_ = 0;
};

}  // namespace rtpro
