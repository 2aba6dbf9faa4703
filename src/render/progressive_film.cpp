#include "rtpro/render/progressive_film.h"

#include <tbb/parallel_for.h>

#include <span>
#include <stdexcept>

namespace rtpro {

ProgressiveFilm::ProgressiveFilm(const TileGrid& grid)
    : grid_(grid), pixels_(grid.region().pixel_count()), tile_rays_(grid.tiles_per_pass()),
      tile_nan_samples_(grid.tiles_per_pass(), 0) {}

void ProgressiveFilm::merge_item(const TileResult& item, bool cumulative) {
  const PixelRegion& region = grid_.region();
  const auto width = static_cast<std::size_t>(region.width());
  const float* packed = item.pixels.data();
  for (int y = item.region.y0; y < item.region.y1; ++y) {
    PixelAccumulator* row = &pixels_[static_cast<std::size_t>(y - region.y0) * width +
                                     static_cast<std::size_t>(item.region.x0 - region.x0)];
    for (int x = 0; x < item.region.width(); ++x, packed += kAccumulatorFloats) {
      if (cumulative)
        row[x] = unpack(packed);
      else
        row[x].merge(unpack(packed));
    }
  }
  const std::size_t tile = item.index % grid_.tiles_per_pass();
  tile_rays_[tile] += item.rays;
  tile_nan_samples_[tile] += item.nan_samples;
}

void ProgressiveFilm::add(TileResult&& item) {
  const std::size_t tiles = grid_.tiles_per_pass();
  if (item.index >= grid_.count() || item.pixels.size() != item.region.pixel_count() * kAccumulatorFloats)
    throw std::logic_error("ProgressiveFilm: an item that is not a work item of this grid");
  const int pass = grid_.pass(item.index);
  std::unique_lock lock(mutex_);
  ++items_in_;
  if (item.cumulative) {
    if (merging_ || !waiting_.empty() || (cumulative_tiles_ > 0 && pass != cumulative_pass_))
      throw std::logic_error("ProgressiveFilm: cumulative items of different passes, or after other items");
    merge_item(item, true);
    cumulative_pass_ = pass;
    if (++cumulative_tiles_ == tiles) merged_ = pass + 1;
    return;
  }
  if (pass < merged_) return;  // summed in a cumulative item already
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
  for (auto ready = waiting_.find(merged_); ready != waiting_.end() && ready->second.count == tiles;
       ready = waiting_.find(merged_)) {
    std::vector<TileResult> items = std::move(ready->second.items);
    waiting_.erase(ready);
    lock.unlock();
    tbb::parallel_for(std::size_t{0}, items.size(), [&](std::size_t i) { merge_item(items[i], false); });
    items.clear();
    lock.lock();
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
  const auto waiting = waiting_.find(pass);
  return waiting != waiting_.end() && !waiting->second.items.empty() &&
         !waiting->second.items[index % grid_.tiles_per_pass()].pixels.empty();
}

void ProgressiveFilm::resolve(const FilmLayout& layout, Image& image) const {
  const PixelRegion& region = grid_.region();
  const auto channels = static_cast<std::size_t>(layout.channel_count());
  tbb::parallel_for(region.y0, region.y1, [&](int y) {
    for (int x = region.x0; x < region.x1; ++x)
      layout.resolve(pixel(x, y), std::span<float>(&image.at(x, y, 0), channels));
  });
}

void ProgressiveFilm::resolve_with_partial_pass(const FilmLayout& layout, Image& image) const {
  resolve(layout, image);
  std::lock_guard lock(mutex_);
  const auto waiting = waiting_.find(merged_);
  if (waiting == waiting_.end()) return;
  const auto channels = static_cast<std::size_t>(layout.channel_count());
  for (const TileResult& item : waiting->second.items) {
    const float* packed = item.pixels.data();
    for (int y = item.region.y0; y < item.region.y1 && packed; ++y)
      for (int x = item.region.x0; x < item.region.x1; ++x, packed += kAccumulatorFloats) {
        PixelAccumulator acc = pixel(x, y);
        acc.merge(unpack(packed));
        layout.resolve(acc, std::span<float>(&image.at(x, y, 0), channels));
      }
  }
}

std::vector<TileResult> ProgressiveFilm::journal_items() const {
  std::lock_guard lock(mutex_);
  std::vector<TileResult> items;
  const std::size_t tiles = grid_.tiles_per_pass();
  if (merged_ > 0)
    for (std::size_t tile = 0; tile < tiles; ++tile) {
      TileResult item;
      item.index = static_cast<std::size_t>(merged_ - 1) * tiles + tile;
      item.region = grid_.tile(tile);
      item.cumulative = true;
      item.rays = tile_rays_[tile];
      item.nan_samples = tile_nan_samples_[tile];
      item.pixels.resize(item.region.pixel_count() * kAccumulatorFloats);
      float* packed = item.pixels.data();
      for (int y = item.region.y0; y < item.region.y1; ++y)
        for (int x = item.region.x0; x < item.region.x1; ++x, packed += kAccumulatorFloats) pack(pixel(x, y), packed);
      items.push_back(std::move(item));
    }
  for (const auto& [pass, waiting] : waiting_)
    for (const TileResult& item : waiting.items)
      if (!item.pixels.empty()) items.push_back(item);
  return items;
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
