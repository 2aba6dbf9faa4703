#include "rtpro/render/progressive_film.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>

namespace rtpro {

ProgressiveFilm::ProgressiveFilm(const TileGrid& grid, const SumLayout& sums)
    : grid_(grid), sums_(sums), pixels_(grid.region().pixel_count() * static_cast<std::size_t>(sums.floats())),
      first_pass_tiles_(grid.tiles_per_pass(), kTileAbsent), tile_rays_(grid.tiles_per_pass()),
      tile_nan_samples_(grid.tiles_per_pass(), 0) {
  pixels_.populate();
}

void ProgressiveFilm::merge_pixels(const TileResult& item, bool set) {
  const std::size_t row_floats = static_cast<std::size_t>(item.region.width() * sums_.floats());
  const float* later = item.pixels.data();
  for (int y = item.region.y0; y < item.region.y1; ++y, later += row_floats) {
    float* row = pixels_.get() + sums_offset(item.region.x0, y);
    if (set) {
      std::copy(later, later + row_floats, row);
      continue;
    }
    sums_.merge(row, later, static_cast<std::size_t>(item.region.width()));
  }
}

void ProgressiveFilm::count_cost(const TileResult& item) {
  const std::size_t tile = item.index % grid_.tiles_per_pass();
  tile_rays_[tile] += item.rays;
  tile_nan_samples_[tile] += item.nan_samples;
}

void ProgressiveFilm::add(TileResult&& item) {
  const std::size_t tiles = grid_.tiles_per_pass();
  if (item.index >= grid_.count() ||
      item.pixels.size() != item.region.pixel_count() * static_cast<std::size_t>(sums_.floats()))
    throw std::logic_error("ProgressiveFilm: an item that is not a work item of this grid");
  const int pass = grid_.pass(item.index);
  std::unique_lock lock(mutex_);
  ++items_in_;
  if (item.cumulative) {
    if (merging_ || !waiting_.empty() || first_pass_in_ > 0 || (cumulative_tiles_ > 0 && pass != cumulative_pass_))
      throw std::logic_error("ProgressiveFilm: cumulative items of different passes, or after other items");
    merge_pixels(item, true);
    count_cost(item);
    cumulative_pass_ = pass;
    if (++cumulative_tiles_ == tiles) merged_ = pass + 1;
    return;
  }
  if (pass < merged_) return;  // summed in a cumulative item already
  if (pass == 0) {
    // The first pass adds to sums of nothing, so its tiles go in as they come (tiles own disjoint
    // pixels) and their items are freed at once: a one-pass render holds no second copy of the film.
    std::uint8_t& state = first_pass_tiles_[item.index];
    if (state != kTileAbsent) return;
    state = kTileMerging;
    ++first_pass_in_;
    lock.unlock();
    // Set rather than added: the sums there are zero, and adding zero changes no sum (a sum is
    // never -0, the one value zero plus it changes, as every sum starts from +0), so the film's
    // rows are written without being read.
    merge_pixels(item, true);
    lock.lock();
    state = kTileMerged;
    count_cost(item);
    if (++first_pass_merged_ == tiles) merge_ready_passes(lock);
    return;
  }
  WaitingPass& waiting = waiting_[pass];
  if (waiting.items.empty()) waiting.items.resize(tiles);
  TileResult& slot = waiting.items[item.index % tiles];
  if (!slot.pixels.empty()) return;
  slot = std::move(item);
  ++waiting.count;
  merge_ready_passes(lock);
}

void ProgressiveFilm::merge_ready_passes(std::unique_lock<std::mutex>& lock) {
  if (merging_) return;  // the merging thread takes this pass too when it is ready
  merging_ = true;
  const std::size_t tiles = grid_.tiles_per_pass();
  for (;;) {
    if (merged_ == 0) {
      if (first_pass_merged_ < tiles) break;  // merged tile by tile as they came
    } else {
      const auto ready = waiting_.find(merged_);
      if (ready == waiting_.end() || ready->second.count < tiles) break;
      std::vector<TileResult> items = std::move(ready->second.items);
      waiting_.erase(ready);
      lock.unlock();
      tbb::parallel_for(std::size_t{0}, items.size(), [&](std::size_t i) { merge_pixels(items[i], false); });
      lock.lock();
      for (const TileResult& item : items) count_cost(item);
    }
    const int pass = merged_++;
    if (on_pass_merged) {
      lock.unlock();
      on_pass_merged(pass);
      lock.lock();
    }
  }
  merging_ = false;
}

int ProgressiveFilm::passes_merged() const {
  std::lock_guard lock(mutex_);
  return merged_;
}

bool ProgressiveFilm::has(std::size_t index) const {
  std::lock_guard lock(mutex_);
  const int pass = grid_.pass(index);
  if (pass < merged_) return true;
  if (pass == 0) return first_pass_tiles_[index] != kTileAbsent;
  const auto waiting = waiting_.find(pass);
  return waiting != waiting_.end() && !waiting->second.items.empty() &&
         !waiting->second.items[index % grid_.tiles_per_pass()].pixels.empty();
}

SampleCounts ProgressiveFilm::resolve(const FilmLayout& layout, Image& image) const {
  const PixelRegion& region = grid_.region();
  // Integer sums, so that the mean is the same however the rows are split.
  struct Counted {
    int min = std::numeric_limits<int>::max(), max = 0;
    std::uint64_t sum = 0;
  };
  const Counted counted = tbb::parallel_reduce(
      tbb::blocked_range<int>(region.y0, region.y1), Counted{},
      [&](const tbb::blocked_range<int>& rows, Counted counts) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
          const float* sums = pixel_sums(region.x0, y);
          layout.resolve_row(sums_, sums, region.width(), &image.at(region.x0, y, 0));
          for (int x = 0; x < region.width(); ++x, sums += sums_.floats()) {
            const int samples = SumLayout::samples(sums);
            counts.min = std::min(counts.min, samples);
            counts.max = std::max(counts.max, samples);
            counts.sum += static_cast<std::uint64_t>(samples);
          }
        }
        return counts;
      },
      [](const Counted& a, const Counted& b) {
        return Counted{std::min(a.min, b.min), std::max(a.max, b.max), a.sum + b.sum};
      });
  return {counted.min, counted.max,
          static_cast<double>(counted.sum) / (double(region.width()) * double(region.height()))};
}

SampleCounts ProgressiveFilm::resolve_with_partial_pass(const FilmLayout& layout, Image& image) const {
  const SampleCounts counts = resolve(layout, image);  // holds the first pass's tiles that are in
  std::lock_guard lock(mutex_);
  if (merged_ == 0) return counts;
  const auto waiting = waiting_.find(merged_);
  if (waiting == waiting_.end()) return counts;
  const auto channels = static_cast<std::size_t>(layout.channel_count());
  const auto floats = static_cast<std::size_t>(sums_.floats());
  std::vector<float> sums(floats);
  for (const TileResult& item : waiting->second.items) {
    const float* later = item.pixels.data();
    for (int y = item.region.y0; y < item.region.y1 && later; ++y)
      for (int x = item.region.x0; x < item.region.x1; ++x, later += floats) {
        const float* merged = pixel_sums(x, y);
        sums.assign(merged, merged + floats);
        sums_.merge(sums.data(), later);
        layout.resolve(sums_.load(sums.data()), std::span<float>(&image.at(x, y, 0), channels));
      }
  }
  return counts;
}

void ProgressiveFilm::visit_journal_items(const std::function<void(const TileResult&)>& visit) const {
  const std::size_t tiles = grid_.tiles_per_pass();
  TileResult item;
  // Through the last merged pass, or the first pass's tiles merged so far (as items of their own).
  // The lock is taken for each copy only: workers keep adding the next pass's items meanwhile.
  for (std::size_t tile = 0; tile < tiles; ++tile) {
    {
      std::lock_guard lock(mutex_);
      if (merged_ == 0 && first_pass_tiles_[tile] != kTileMerged) continue;
      item.index = merged_ > 0 ? static_cast<std::size_t>(merged_ - 1) * tiles + tile : tile;
      item.region = grid_.tile(tile);
      item.cumulative = merged_ > 0;
      item.rays = tile_rays_[tile];
      item.nan_samples = tile_nan_samples_[tile];
      const std::size_t row_floats = static_cast<std::size_t>(item.region.width() * sums_.floats());
      item.pixels.resize(item.region.pixel_count() * static_cast<std::size_t>(sums_.floats()));
      for (int y = item.region.y0; y < item.region.y1; ++y) {
        const float* row = pixel_sums(item.region.x0, y);
        std::copy(row, row + row_floats,
                  item.pixels.begin() +
                      static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y - item.region.y0) * row_floats));
      }
    }
    visit(item);
  }
  // A waiting pass leaves the map only when the merging thread merges it: the caller's, or none.
  std::vector<int> passes;
  {
    std::lock_guard lock(mutex_);
    for (const auto& entry : waiting_) passes.push_back(entry.first);
  }
  for (const int pass : passes)
    for (std::size_t slot = 0; slot < tiles; ++slot) {
      {
        std::lock_guard lock(mutex_);
        const auto waiting = waiting_.find(pass);
        if (waiting == waiting_.end() || slot >= waiting->second.items.size() ||
            waiting->second.items[slot].pixels.empty())
          continue;
        item = waiting->second.items[slot];
      }
      visit(item);
    }
}

RayCounts ProgressiveFilm::rays() const {
  std::lock_guard lock(mutex_);
  RayCounts total;
  for (const RayCounts& rays : tile_rays_) total += rays;
  for (const auto& [pass, waiting] : waiting_)
    for (const TileResult& item : waiting.items) total += item.rays;
  return total;
}

std::uint64_t ProgressiveFilm::nan_samples() const {
  std::lock_guard lock(mutex_);
  std::uint64_t total = 0;
  for (std::uint64_t n : tile_nan_samples_) total += n;
  for (const auto& [pass, waiting] : waiting_)
    for (const TileResult& item : waiting.items) total += item.nan_samples;
  return total;
}

std::size_t ProgressiveFilm::items_in() const {
  std::lock_guard lock(mutex_);
  return items_in_;
}

}  // namespace rtpro
