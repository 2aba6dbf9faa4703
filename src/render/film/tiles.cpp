#include "rtpro/render/tiles.h"

#include <algorithm>

namespace rtpro {

// A tile larger than the region covers it all the same; clamped, the sums below stay within int
// (--tile-size 2147483647 overflowed them into a grid of no tiles).
TileGrid::TileGrid(const PixelRegion& region, int tile_size, int passes)
    : region_(region), tile_size_(std::min(tile_size, std::max({region.width(), region.height(), 1}))),
      columns_(static_cast<std::size_t>((region.width() + tile_size_ - 1) / tile_size_)),
      rows_(static_cast<std::size_t>((region.height() + tile_size_ - 1) / tile_size_)), passes_(std::max(passes, 1)) {}

PixelRegion TileGrid::tile(std::size_t item) const {
  const std::size_t index = item % tiles_per_pass();
  const int x0 = region_.x0 + static_cast<int>(index % columns_) * tile_size_;
  const int y0 = region_.y0 + static_cast<int>(index / columns_) * tile_size_;
  return {x0, y0, std::min(x0 + tile_size_, region_.x1), std::min(y0 + tile_size_, region_.y1)};
}

std::optional<std::size_t> AllTilesSource::next() {
  if (cancel_ && cancel_->load(std::memory_order_relaxed)) return std::nullopt;
  const std::size_t index = next_.fetch_add(1, std::memory_order_relaxed);
  if (index >= count_) return std::nullopt;
  return index;
}

std::optional<std::size_t> TileListSource::next() {
  if (cancel_ && cancel_->load(std::memory_order_relaxed)) return std::nullopt;
  const std::size_t position = next_.fetch_add(1, std::memory_order_relaxed);
  if (position >= indices_.size()) return std::nullopt;
  return indices_[position];
}

}  // namespace rtpro
