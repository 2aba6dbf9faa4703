#pragma once
// A finished work item (a tile in a pass) as bytes, for the two places one travels before it lands
// in the film: a resume journal on disk and a message from one rank to another. The bytes carry
// the item's index, region, statistics, whether it is cumulative, and its floats (bit for bit) and end in a 64-bit XXH3 checksum of all
// that precedes it, so a torn or corrupted record is recognised and dropped, never trusted.
// Native byte order: every rank of a job and every resume runs on the same architecture.
#include "rtpro/render/tiles.h"

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace rtpro {

// Bytes before the pixels: enough to tell, with the grid, how long the whole record is.
inline constexpr std::size_t kTileRecordHeaderBytes = 80;

std::size_t tile_record_size(const PixelRegion& region, int channel_count);

std::vector<std::byte> encode_tile(const TileResult& tile, int channel_count);

// The record's full size from its first kTileRecordHeaderBytes, or nothing if they are not the
// start of a record of this grid (bad magic, channel count, index or region).
std::optional<std::size_t> tile_record_size_from_header(std::span<const std::byte> header, const TileGrid& grid,
                                                        int channel_count);

// The tile, or nothing when the bytes are not exactly one intact record of this grid.
std::optional<TileResult> decode_tile(std::span<const std::byte> record, const TileGrid& grid, int channel_count);

}  // namespace rtpro
