#include "rtpro/job/tile_codec.h"

#include <xxhash.h>

#include <cstdint>
#include <cstring>

namespace rtpro {

namespace {

constexpr std::uint32_t kTileMagic = 0x32505452;  // "RTP2": records of work items
constexpr std::uint32_t kCumulative = 1;

struct RecordHeader {
  std::uint32_t magic;
  std::uint32_t channel_count;
  std::uint64_t index;
  std::int32_t x0, y0, x1, y1;
  RayCounts rays;  // by kind, in RayKind order (ray_counts.h)
  std::uint64_t nan_samples;
  std::uint32_t flags;  // kCumulative
  std::uint32_t reserved;
};
static_assert(sizeof(RecordHeader) == kTileRecordHeaderBytes);

bool matches_grid(const RecordHeader& h, const TileGrid& grid, int channel_count) {
  if (h.magic != kTileMagic || h.channel_count != static_cast<std::uint32_t>(channel_count) ||
      h.index >= grid.count() || (h.flags & ~kCumulative) != 0 || h.reserved != 0)
    return false;
  const PixelRegion expected = grid.tile(static_cast<std::size_t>(h.index));
  return h.x0 == expected.x0 && h.y0 == expected.y0 && h.x1 == expected.x1 && h.y1 == expected.y1;
}

}  // namespace

std::size_t tile_record_size(const PixelRegion& region, int channel_count) {
  return kTileRecordHeaderBytes + region.pixel_count() * static_cast<std::size_t>(channel_count) * sizeof(float) +
         sizeof(std::uint64_t);
}

std::vector<std::byte> encode_tile(const TileResult& tile, int channel_count) {
  const RecordHeader header{kTileMagic,
                            static_cast<std::uint32_t>(channel_count),
                            tile.index,
                            tile.region.x0,
                            tile.region.y0,
                            tile.region.x1,
                            tile.region.y1,
                            tile.rays,
                            tile.nan_samples,
                            tile.cumulative ? kCumulative : 0u,
                            0u};
  std::vector<std::byte> bytes(tile_record_size(tile.region, channel_count));
  const std::size_t pixel_bytes = tile.pixels.size() * sizeof(float);
  if (kTileRecordHeaderBytes + pixel_bytes + sizeof(std::uint64_t) != bytes.size())
    throw std::logic_error("encode_tile: the tile's pixels do not fill its region");
  std::memcpy(bytes.data(), &header, sizeof header);
  std::memcpy(bytes.data() + kTileRecordHeaderBytes, tile.pixels.data(), pixel_bytes);
  const std::uint64_t checksum = XXH3_64bits(bytes.data(), bytes.size() - sizeof checksum);
  std::memcpy(bytes.data() + bytes.size() - sizeof checksum, &checksum, sizeof checksum);
  return bytes;
}

std::optional<std::size_t> tile_record_size_from_header(std::span<const std::byte> header, const TileGrid& grid,
                                                        int channel_count) {
  if (header.size() < kTileRecordHeaderBytes) return std::nullopt;
  RecordHeader h;
  std::memcpy(&h, header.data(), sizeof h);
  if (!matches_grid(h, grid, channel_count)) return std::nullopt;
  return tile_record_size(grid.tile(static_cast<std::size_t>(h.index)), channel_count);
}

std::optional<TileResult> decode_tile(std::span<const std::byte> record, const TileGrid& grid, int channel_count) {
  const std::optional<std::size_t> size = tile_record_size_from_header(record, grid, channel_count);
  if (!size || *size != record.size()) return std::nullopt;
  std::uint64_t checksum;
  std::memcpy(&checksum, record.data() + record.size() - sizeof checksum, sizeof checksum);
  if (XXH3_64bits(record.data(), record.size() - sizeof checksum) != checksum) return std::nullopt;
  RecordHeader h;
  std::memcpy(&h, record.data(), sizeof h);
  TileResult tile;
  tile.index = static_cast<std::size_t>(h.index);
  tile.region = {h.x0, h.y0, h.x1, h.y1};
  tile.rays = h.rays;
  tile.nan_samples = h.nan_samples;
  tile.cumulative = (h.flags & kCumulative) != 0;
  tile.pixels.resize(tile.region.pixel_count() * static_cast<std::size_t>(channel_count));
  std::memcpy(tile.pixels.data(), record.data() + kTileRecordHeaderBytes, tile.pixels.size() * sizeof(float));
  return tile;
}

}  // namespace rtpro
