#include "exr_output.h"

#include "exr_zip_block.h"
#include "image_metadata.h"
#include "pixel_encoding.h"
#include "rtpro/core/error.h"
#include "rtpro/image/atomic_file_replacement.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVersion.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <set>
#include <span>
#include <vector>

namespace rtpro {

namespace {

static_assert(std::endian::native == std::endian::little, "EXR stores little-endian numbers, copied as they are");

// The file in memory: OpenEXR writes the header into it, the offsets and chunks follow.
class MemoryStream final : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}

  void write(const char c[], int n) override {
    const std::size_t end = position_ + static_cast<std::size_t>(n);
    if (end > bytes_.size()) bytes_.resize(end);
    std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
    position_ = end;
  }
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t position) override { position_ = static_cast<std::size_t>(position); }

  void reserve(std::size_t size) { bytes_.reserve(size); }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
  std::size_t position_ = 0;
};

// OpenImageIO's EXR writer stores its standard names under OpenEXR's (its exr_meta_translation),
// and its reader maps them back.
std::string exr_attribute_name(const std::string& name) {
  if (name == "DateTime") return "capDate";
  if (name == "ImageDescription" || name == "description") return "comments";
  if (name == "Copyright") return "owner";
  return name;
}

Imf::Header describe(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options) {
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  std::set<std::string> names;
  for (const std::string& name : image.channels) {
    if (name.empty() || !names.insert(name).second)
      throw RuntimeError("cannot write " + file.string() + ": channel names must be distinct and not empty");
    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  }
  // EXR's own statement of the primaries.
  const float* xy = kRec709Chromaticities;
  Imf::addChromaticities(header, Imf::Chromaticities({xy[0], xy[1]}, {xy[2], xy[3]}, {xy[4], xy[5]}, {xy[6], xy[7]}));
  for (const auto& [key, value] : scene_linear_metadata(options))
    header.insert(exr_attribute_name(key), Imf::StringAttribute(value));
  return header;
}

// EXR keeps channels sorted by name, and each scanline of a chunk holds them in that order.
std::vector<std::size_t> channel_order(const Image& image) {
  std::vector<std::size_t> order(image.channels.size());
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return image.channels[a] < image.channels[b]; });
  return order;
}

// Scanlines y0 .. y0 + lines as a chunk holds them: each line's channels one after another, in the
// file's channel order.
void gather_chunk(const Image& image, const std::vector<std::size_t>& order, int y0, int lines,
                  std::vector<std::uint8_t>& raw) {
  const std::size_t width = static_cast<std::size_t>(image.width), channels = image.channels.size();
  raw.resize(static_cast<std::size_t>(lines) * width * channels * sizeof(float));
  std::uint8_t* out = raw.data();
  for (int y = y0; y < y0 + lines; ++y) {
    const float* row = image.data.data() + static_cast<std::size_t>(y) * width * channels;
    for (std::size_t channel : order)
      for (std::size_t x = 0; x < width; ++x, out += sizeof(float))
        std::memcpy(out, &row[x * channels + channel], sizeof(float));
  }
}

// Names longer than 31 bytes need EXR's long-names flag, which readers older than OpenEXR 1.7
// refuse: set only then, as OpenEXR's own writer does.
bool uses_long_names(const Imf::Header& header) {
  constexpr std::size_t kShortNameLength = 31;
  for (auto it = header.begin(); it != header.end(); ++it)
    if (std::strlen(it.name()) > kShortNameLength || std::strlen(it.attribute().typeName()) > kShortNameLength)
      return true;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
    if (std::strlen(it.name()) > kShortNameLength) return true;
  return false;
}

template <typename Number>
void append_le(MemoryStream& stream, Number value) {
  char bytes[sizeof(Number)];
  std::memcpy(bytes, &value, sizeof(Number));
  stream.write(bytes, sizeof(Number));
}

}  // namespace

bool is_exr_file(const std::filesystem::path& file) {
  const std::string extension = lowercase_extension(file);
  return extension == ".exr" || extension == ".sxr" || extension == ".mxr";
}

std::string encode_exr(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options) {
  require_writable_image(file, image);
  try {
    const Imf::Header header = describe(file, image, options);
    header.sanityCheck();
    const std::vector<std::size_t> order = channel_order(image);
    const std::uint64_t chunk_bytes = std::uint64_t{kExrZipScanlines} * static_cast<std::uint64_t>(image.width) *
                                      image.channels.size() * sizeof(float);
    if (chunk_bytes > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max()))
      throw RuntimeError("cannot write " + file.string() + ": " + std::to_string(kExrZipScanlines) +
                         " scanlines of the image exceed the 2 GiB an EXR chunk can hold");

    // Chunks compressed on the threads the render may use (its TBB cap).
    const int chunks = (image.height + kExrZipScanlines - 1) / kExrZipScanlines;
    std::vector<std::vector<std::uint8_t>> stored(static_cast<std::size_t>(chunks));
    tbb::parallel_for(tbb::blocked_range<int>(0, chunks), [&](const tbb::blocked_range<int>& range) {
      ExrZipEncoder encoder;
      std::vector<std::uint8_t> raw;
      for (int chunk = range.begin(); chunk != range.end(); ++chunk) {
        const int y0 = chunk * kExrZipScanlines;
        gather_chunk(image, order, y0, std::min(kExrZipScanlines, image.height - y0), raw);
        const std::span<const std::uint8_t> bytes = encoder.encode(raw);
        stored[static_cast<std::size_t>(chunk)].assign(bytes.begin(), bytes.end());
      }
    });

    // The layout of a single-part scanline file: magic number and version, the header, the
    // offset of every chunk, then the chunks in increasing y, each with its y and size.
    MemoryStream stream;
    append_le(stream, static_cast<std::int32_t>(Imf::MAGIC));
    append_le(stream,
              static_cast<std::int32_t>(Imf::EXR_VERSION | (uses_long_names(header) ? Imf::LONG_NAMES_FLAG : 0)));
    header.writeTo(stream);
    std::uint64_t offset = stream.tellp() + sizeof(std::uint64_t) * static_cast<std::uint64_t>(chunks);
    for (const std::vector<std::uint8_t>& bytes : stored) {
      append_le(stream, offset);
      offset += 2 * sizeof(std::int32_t) + bytes.size();
    }
    // Each chunk freed once copied, so the file and the chunks together take one copy's memory.
    stream.reserve(offset);
    for (int chunk = 0; chunk < chunks; ++chunk) {
      std::vector<std::uint8_t>& bytes = stored[static_cast<std::size_t>(chunk)];
      append_le(stream, static_cast<std::int32_t>(chunk * kExrZipScanlines));
      append_le(stream, static_cast<std::int32_t>(bytes.size()));
      stream.write(reinterpret_cast<const char*>(bytes.data()), static_cast<int>(bytes.size()));
      std::vector<std::uint8_t>().swap(bytes);
    }
    return stream.take();
  } catch (const RuntimeError&) {
    throw;
  } catch (const std::exception& error) {
    throw RuntimeError("cannot write " + file.string() + ": " + error.what());
  }
}

void write_exr(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options) {
  check_replaceable(file);
  write_file_atomically(file, encode_exr(file, image, options));
}

}  // namespace rtpro
