#include "exr_zip_block.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace rtpro {
namespace exr_zip_block_test {

// A reader's side of a ZIP chunk, written from the file format's description: inflate the zlib
// stream, add each difference (less 128) to the byte before it, then put the even bytes (the
// first half) and the odd bytes (the second half) back in turn.
std::vector<std::uint8_t> decode(std::span<const std::uint8_t> stored, std::size_t raw_size) {
  if (stored.size() == raw_size) return {stored.begin(), stored.end()};
  std::vector<std::uint8_t> filtered(raw_size);
  uLongf size = static_cast<uLongf>(raw_size);
  EXPECT_EQ(uncompress(filtered.data(), &size, stored.data(), static_cast<uLong>(stored.size())), Z_OK);
  EXPECT_EQ(size, raw_size);
  for (std::size_t i = 1; i < filtered.size(); ++i)
    filtered[i] = static_cast<std::uint8_t>(filtered[i - 1] + filtered[i] - 128);
  std::vector<std::uint8_t> raw(raw_size);
  const std::size_t half = (raw_size + 1) / 2;
  for (std::size_t i = 0; i < raw_size; ++i) raw[i] = i % 2 == 0 ? filtered[i / 2] : filtered[half + i / 2];
  return raw;
}

// Flat runs of a few values, like a rendered background or an object-id channel.
std::vector<std::uint8_t> flat_floats(std::size_t count) {
  std::vector<std::uint8_t> bytes(count * sizeof(float));
  for (std::size_t i = 0; i < count; ++i) {
    const float value = static_cast<float>((i / 50) % 20) * 0.05f;
    std::memcpy(bytes.data() + i * sizeof(float), &value, sizeof(float));
  }
  return bytes;
}

std::vector<std::uint8_t> noise(std::size_t size) {
  std::vector<std::uint8_t> bytes(size);
  std::uint32_t state = 12345;
  for (std::uint8_t& byte : bytes) {
    state = state * 1664525u + 1013904223u;
    byte = static_cast<std::uint8_t>(state >> 24);
  }
  return bytes;
}

TEST(ExrZipEncoder, FlatValuesAreCompressedAndDecodeToTheSameBytes) {
  const std::vector<std::uint8_t> raw = flat_floats(16 * 640 * 3);
  ExrZipEncoder encoder;
  const std::span<const std::uint8_t> stored = encoder.encode(raw);
  EXPECT_LT(stored.size(), raw.size() / 2);
  EXPECT_EQ(stored[0] & 0x0F, 8) << "a zlib stream (deflate) starts with method 8";
  EXPECT_EQ(decode(stored, raw.size()), raw);
}

TEST(ExrZipEncoder, KeepsWhatDoesNotCompressAsItIs) {
  const std::vector<std::uint8_t> raw = noise(4096);
  ExrZipEncoder encoder;
  const std::span<const std::uint8_t> stored = encoder.encode(raw);
  EXPECT_EQ(std::vector<std::uint8_t>(stored.begin(), stored.end()), raw);
}

TEST(ExrZipEncoder, OneEncoderServesChunksOfEverySize) {
  ExrZipEncoder encoder;
  for (std::size_t size : {std::size_t{4000}, std::size_t{7}, std::size_t{1}, std::size_t{0}, std::size_t{100001}}) {
    std::vector<std::uint8_t> raw = flat_floats((size + 3) / 4);
    raw.resize(size);
    EXPECT_EQ(decode(encoder.encode(raw), raw.size()), raw) << size << " bytes";
  }
}

}  // namespace exr_zip_block_test
}  // namespace rtpro
