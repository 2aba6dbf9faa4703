#pragma once
// One chunk of an EXR file in ZIP compression, made as OpenEXR's own ZIP compressor makes it: the
// bytes split into their even and odd halves, each byte replaced by its difference to the byte
// before it (plus 128), then one zlib stream. OpenEXR 3.1 compresses with zlib; libdeflate writes
// the same stream format 2.7-3.1x faster (third_party_notes/libdeflate.md).
#include <cstdint>
#include <span>
#include <vector>

struct libdeflate_compressor;

namespace rtpro {

// Scanlines per chunk in EXR's ZIP_COMPRESSION.
inline constexpr int kExrZipScanlines = 16;

// Not thread-safe: one per thread. Holds the compressor's hash tables and scratch buffers, so an
// encoder is best reused for many chunks.
class ExrZipEncoder {
 public:
  ExrZipEncoder();
  ~ExrZipEncoder();
  ExrZipEncoder(const ExrZipEncoder&) = delete;
  ExrZipEncoder& operator=(const ExrZipEncoder&) = delete;

  // The chunk as the file stores it: the compressed stream, or `raw` itself when compressing
  // would not make it smaller (readers tell the two apart by the size). Valid until the next call.
  std::span<const std::uint8_t> encode(std::span<const std::uint8_t> raw);

 private:
  libdeflate_compressor* compressor_;
  std::vector<std::uint8_t> filtered_;
  std::vector<std::uint8_t> compressed_;
};

}  // namespace rtpro
