// Tile records: every bit of a tile comes back, and any damage is recognised.
#include "rtpro/job/tile_codec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace rtpro {
namespace tile_codec_test {

TileResult sample_tile(const TileGrid& grid, std::size_t index, int channels) {
  TileResult tile;
  tile.index = index;
  tile.region = grid.tile(index);
  tile.rays = {11, 22, 33, 44};
  tile.nan_samples = 5;
  tile.pixels.resize(tile.region.pixel_count() * static_cast<std::size_t>(channels));
  for (std::size_t i = 0; i < tile.pixels.size(); ++i) tile.pixels[i] = std::nextafter(0.1f * float(i), 1e9f);
  tile.pixels[0] = -0.0f;
  tile.pixels[1] = std::numeric_limits<float>::denorm_min();
  return tile;
}

TEST(TileCodec, RoundTripsEveryBit) {
  const TileGrid grid({0, 0, 70, 45}, 16);  // edge tiles are smaller
  for (std::size_t index : {std::size_t(0), std::size_t(4), grid.count() - 1}) {
    const TileResult tile = sample_tile(grid, index, 5);
    const std::vector<std::byte> bytes = encode_tile(tile, 5);
    EXPECT_EQ(bytes.size(), tile_record_size(tile.region, 5));
    EXPECT_EQ(tile_record_size_from_header(bytes, grid, 5), bytes.size());
    const std::optional<TileResult> back = decode_tile(bytes, grid, 5);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->index, index);
    EXPECT_EQ(back->region.x1, tile.region.x1);
    EXPECT_EQ(back->region.y1, tile.region.y1);
    EXPECT_EQ(back->rays[RayKind::kRefraction], 44u);
    EXPECT_EQ(back->nan_samples, 5u);
    ASSERT_EQ(back->pixels.size(), tile.pixels.size());
    EXPECT_EQ(std::memcmp(back->pixels.data(), tile.pixels.data(), tile.pixels.size() * sizeof(float)), 0);
  }
}

// Journals and a job's messages hold records in this layout: the ray counts at bytes 32 to 63 of
// the header, after the region, camera, shadow, reflection and refraction, 64 bits each.
TEST(TileCodec, TheRayCountsLieAfterTheRegionInKindOrder) {
  const TileGrid grid({0, 0, 70, 45}, 16);
  const std::vector<std::byte> bytes = encode_tile(sample_tile(grid, 0, 5), 5);
  for (std::size_t k = 0; k < kRayKindCount; ++k) {
    std::uint64_t count = 0;
    std::memcpy(&count, bytes.data() + 32 + 8 * k, sizeof count);
    EXPECT_EQ(count, 11u * (k + 1)) << ray_kind_name(kRayKinds[k]);
  }
}

TEST(TileCodec, EveryFlippedByteIsRefused) {
  const TileGrid grid({0, 0, 8, 8}, 4);
  const std::vector<std::byte> bytes = encode_tile(sample_tile(grid, 3, 3), 3);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::vector<std::byte> damaged = bytes;
    damaged[i] ^= std::byte{0x10};
    EXPECT_FALSE(decode_tile(damaged, grid, 3)) << "byte " << i;
  }
}

TEST(TileCodec, TruncatedOrForeignRecordsAreRefused) {
  const TileGrid grid({0, 0, 8, 8}, 4);
  std::vector<std::byte> bytes = encode_tile(sample_tile(grid, 1, 3), 3);
  EXPECT_FALSE(decode_tile(std::span(bytes).first(bytes.size() - 1), grid, 3));
  EXPECT_FALSE(tile_record_size_from_header(std::span(bytes).first(kTileRecordHeaderBytes - 1), grid, 3));
  EXPECT_FALSE(decode_tile(bytes, grid, 4));                       // another channel layout
  EXPECT_FALSE(decode_tile(bytes, TileGrid({0, 0, 8, 8}, 8), 3));  // another tile size
  EXPECT_FALSE(decode_tile(bytes, TileGrid({0, 0, 4, 4}, 4), 3));  // index beyond the grid
}

}  // namespace tile_codec_test
}  // namespace rtpro
