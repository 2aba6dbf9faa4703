#include "rtpro/image/image_io.h"

#include "rtpro/image/atomic_file_replacement.h"

#include "display_encoding.h"
#include "direct_output.h"
#include "exr_input.h"
#include "image_metadata.h"
#include "pixel_encoding.h"
#include "image_format_sniff.h"
#include "image_file_check.h"
#include "image_header_check.h"
#include "image_read_budget.h"
#include "image_read_limits.h"
#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string_view>
#include <variant>
#include <vector>

namespace rtpro {

namespace {

using PixelBuffer = std::variant<std::vector<float>, std::vector<std::uint8_t>, std::vector<std::uint16_t>>;

// OpenImageIO reports some failures (an unknown extension, a failed open) only through its global
// error, others only through the ImageInput/ImageOutput: collect both.
std::string oiio_errors(std::string object_error) {
  const std::string global_error = OIIO::geterror();
  if (object_error.empty()) return global_error.empty() ? "unknown OpenImageIO error" : global_error;
  return global_error.empty() ? object_error : object_error + "; " + global_error;
}

// Checked before anything touches the disk, so an unknown extension creates no file.
std::unique_ptr<OIIO::ImageOutput> writer_for(const std::filesystem::path& file) {
  auto output = OIIO::ImageOutput::create(file.string());
  if (!output) {
    const std::string extension = file.extension().string();
    throw InputError(SourceLocation{file.string()},
                     (extension.empty() ? std::string("no file extension to choose an image format from")
                                        : "unsupported image format \"" + extension + "\"") +
                         " (" + oiio_errors("") + ")");
  }
  return output;
}

// All channels, named as given, when the format takes any number of them; else R, G, B.
std::vector<float> scene_linear_channels(const Image& image, int channel_count) {
  if (channel_count == image.channel_count()) return image.data;
  std::vector<float> values;
  values.reserve(static_cast<std::size_t>(image.width) * image.height * channel_count);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < channel_count; ++c) values.push_back(image.at(x, y, c));
  return values;
}

void describe_scene_linear(OIIO::ImageSpec& spec, const Image& image, bool any_channel_count,
                           const ImageWriteOptions& options) {
  const int channel_count = any_channel_count ? image.channel_count() : std::min(image.channel_count(), 3);
  spec = OIIO::ImageSpec(image.width, image.height, channel_count, OIIO::TypeDesc::FLOAT);
  spec.channelnames.assign(image.channels.begin(), image.channels.begin() + channel_count);
  // As in an EXR (exr_output.h): the primaries in the standard chromaticities attribute, which
  // the float formats keep where they keep any colour information, not oiio:ColorSpace.
  spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), kRec709Chromaticities);
  spec.attribute("compression", "zip");
  for (const auto& [key, value] : scene_linear_metadata(options)) spec.attribute(key, value);
}

PixelBuffer encode_display_referred(OIIO::ImageSpec& spec, const Image& image, PixelEncoding encoding,
                                    const ImageWriteOptions& options) {
  const DisplayEncoding display = display_encoding(options);
  const bool sixteen_bits = encoding == PixelEncoding::kDisplay16Bit;
  spec = OIIO::ImageSpec(image.width, image.height, 3, sixteen_bits ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
  // OpenImageIO records the encoding where the format has a way to say it; an untagged file is
  // read as sRGB anyway.
  if (display.srgb) spec.attribute("oiio:ColorSpace", "sRGB");
  for (const auto& [key, value] : image_metadata(display.description, options)) spec.attribute(key, value);
  if (sixteen_bits) return encode_for_display_16bit(image, display.transform);
  return encode_for_display_8bit(image, display.transform);
}

bool write_with(OIIO::ImageOutput& output, const std::string& name, const OIIO::ImageSpec& spec,
                const PixelBuffer& pixels) {
  if (!output.open(name, spec)) return false;
  const bool written = std::visit(
      [&](const auto& values) {
        using Value = typename std::decay_t<decltype(values)>::value_type;
        return output.write_image(OIIO::BaseTypeFromC<Value>::value, values.data());
      },
      pixels);
  return output.close() && written;
}

// OpenImageIO's TIFF writer fails on its Exif block when it writes to memory (2.4.7).
bool encodes_to_memory(OIIO::ImageOutput& output, const std::filesystem::path& file) {
  const std::string extension = lowercase_extension(file);
  return output.supports("ioproxy") && extension != ".tif" && extension != ".tiff";
}

// Reads every pixel of a file just written by path: OpenImageIO's writers do not all report a
// short write (a full disk once left a 0-byte EXR behind an "ok"), its readers do.
void verify_written(const std::filesystem::path& temporary, const std::filesystem::path& file,
                    const OIIO::ImageSpec& spec) {
  const auto input = OIIO::ImageInput::open(temporary.string());
  bool complete = input && input->spec().width == spec.width && input->spec().height == spec.height &&
                  input->spec().nchannels == spec.nchannels;
  constexpr int kRows = 64;  // in bands, so the check needs little memory whatever the image size
  std::vector<float> band(static_cast<std::size_t>(spec.width) * kRows * std::max(spec.nchannels, 1));
  for (int y = 0; complete && y < spec.height; y += kRows)
    complete = input->read_scanlines(0, 0, y, std::min(y + kRows, spec.height), 0, 0, spec.nchannels,
                                     OIIO::TypeDesc::FLOAT, band.data());
  if (!complete)
    throw RuntimeError("cannot write " + file.string() + ": the written file does not read back (" +
                       oiio_errors(input ? input->geterror() : "") + ")");
}

// Formats OpenImageIO can encode to memory are encoded there and written by the atomic writer,
// which checks every write; the others are written to its temporary file and read back.
void write_pixels(const std::filesystem::path& file, const OIIO::ImageSpec& spec, const PixelBuffer& pixels) {
  check_replaceable(file);
  const auto output = OIIO::ImageOutput::create(file.string());
  if (!output) throw RuntimeError("cannot write " + file.string() + ": " + oiio_errors(""));
  if (encodes_to_memory(*output, file)) {
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput proxy(encoded);
    OIIO::ImageSpec memory_spec = spec;
    void* proxy_pointer = &proxy;
    memory_spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy_pointer);
    if (!write_with(*output, file.string(), memory_spec, pixels))
      throw RuntimeError("cannot write " + file.string() + ": " + oiio_errors(output->geterror()));
    write_file_atomically(file, {reinterpret_cast<const char*>(encoded.data()), encoded.size()});
    return;
  }
  AtomicFileReplacement replacement(file);
  const std::string temporary = replacement.temporary_path().string();
  if (!write_with(*output, temporary, spec, pixels))
    throw RuntimeError("cannot write " + file.string() + ": " + oiio_errors(output->geterror()));
  verify_written(replacement.temporary_path(), file, spec);
  replacement.commit();
}

// Reads an image a band of rows at a time in the file's own pixel types and converts each band
// to float here. OpenImageIO 2.4's converting read_scanlines allocates a 64 MB buffer per call
// whatever the image's size (its chunk is 2^26 bytes of scanlines: most of a fuzz execution's time
// under ASan), and on a tiled file it divides by a rows-per-strip of zero (SIGFPE: every tiled TIFF
// or EXR crashed `rtpro compare`). Tiles are read one whole tile at a time: the OpenEXR reader's
// read_native_tiles writes a partial edge tile past the caller's rectangle (CVE-2026-63422, fixed
// only in OpenImageIO 3.x).
//
// A TIFF whose PhotometricInterpretation is MinIsWhite is read one scanline per call: on whole
// deflate strips OpenImageIO 2.4 inverts nchannels times too many values (stripvals * stripchans
// in TIFFInput::read_native_scanlines), writing up to (nchannels - 1) strips past the caller's
// buffer (a fuzz finding: a 397-byte TIFF of 5x32864 RGB pixels). So is a TIFF whose RowsPerStrip
// is not between 1 and its height: for whole strips the library sizes its compressed-strip scratch
// from RowsPerStrip (an int product that overflows), not from the rows it reads, and a 366-byte
// deflate TIFF 5 pixels wide declaring 704,662,861 rows per strip asked for 5.6 PB (a fuzz
// finding). RowsPerStrip above the height is legal (it means one strip), so such files are read,
// one scanline per call. And every buffer the library
// writes into ends in a guard of known bytes, checked after each call: an overrun it makes on a
// file nobody has met yet is refused as an input error instead of passing silently into the heap.
class NativeBands {
 public:
  NativeBands(OIIO::ImageInput& input, const OIIO::ImageSpec& spec, int band_rows, const SourceLocation& where)
      : input_(input), spec_(spec), where_(where), pixel_bytes_(spec.pixel_bytes(/*native=*/true)),
        row_bytes_(pixel_bytes_ * static_cast<std::size_t>(spec.width)),
        row_by_row_(std::string_view(input.format_name()) == "tiff" &&
                    (spec.get_int_attribute("tiff:PhotometricInterpretation", -1) == 0 ||
                     spec.get_int_attribute("tiff:RowsPerStrip", 0) < 1 ||
                     spec.get_int_attribute("tiff:RowsPerStrip", 0) > spec.height)),
        native_(row_bytes_ * static_cast<std::size_t>(band_rows) + kGuardBytes, kGuardByte),
        tile_(spec.tile_width > 0 ? static_cast<std::size_t>(spec.tile_bytes(/*native=*/true)) + kGuardBytes : 0,
              kGuardByte) {}

  // Rows [y, end) of the image (counted from its data window's top) as floats, channel after
  // channel; false when the reader fails (its error is on the ImageInput).
  bool read(int y, int end, float* out) {
    if (!(spec_.tile_width > 0 ? read_tiles(y, end) : read_scanlines(y, end))) return false;
    return convert(end - y, out);
  }

 private:
  static constexpr std::size_t kGuardBytes = 4096;
  static constexpr unsigned char kGuardByte = 0xA5;

  void require_guard_intact(const std::vector<unsigned char>& buffer) const {
    static const std::vector<unsigned char> guard(kGuardBytes, kGuardByte);
    if (std::memcmp(buffer.data() + buffer.size() - kGuardBytes, guard.data(), kGuardBytes) != 0)
      throw InputError(where_, "the image library wrote past the pixels it was asked for while decoding this " +
                                   std::string(input_.format_name()) + " file; it is not read");
  }

  bool read_scanlines(int y, int end) {
    if (row_by_row_) {
      for (int row = y; row < end; ++row)
        if (!input_.read_native_scanline(0, 0, spec_.y + row, spec_.z,
                                         native_.data() + static_cast<std::size_t>(row - y) * row_bytes_))
          return false;
    } else if (!input_.read_native_scanlines(0, 0, spec_.y + y, spec_.y + end, spec_.z, native_.data())) {
      return false;
    }
    require_guard_intact(native_);
    return true;
  }

  bool read_tiles(int y, int end) {
    const std::size_t tile_row_bytes = pixel_bytes_ * static_cast<std::size_t>(spec_.tile_width);
    for (int x = 0; x < spec_.width; x += spec_.tile_width) {
      if (!input_.read_native_tile(0, 0, spec_.x + x, spec_.y + y, spec_.z, tile_.data())) return false;
      require_guard_intact(tile_);
      const std::size_t columns_bytes =
          pixel_bytes_ * static_cast<std::size_t>(std::min(spec_.tile_width, spec_.width - x));
      for (int row = 0; row < end - y; ++row)
        std::memcpy(
            native_.data() + static_cast<std::size_t>(row) * row_bytes_ + pixel_bytes_ * static_cast<std::size_t>(x),
            tile_.data() + static_cast<std::size_t>(row) * tile_row_bytes, columns_bytes);
    }
    return true;
  }

  bool convert(int rows, float* out) {
    const std::size_t values = static_cast<std::size_t>(spec_.width) * static_cast<std::size_t>(spec_.nchannels);
    if (spec_.channelformats.empty())
      return OIIO::convert_pixel_values(spec_.format, native_.data(), OIIO::TypeDesc::FLOAT, out,
                                        static_cast<int>(values) * rows);
    // Per-channel types (an EXR of half colour and float depth): one channel at a time.
    std::size_t offset = 0;
    for (int c = 0; c < spec_.nchannels; ++c) {
      const OIIO::TypeDesc type = spec_.channelformats[static_cast<std::size_t>(c)];
      if (!OIIO::convert_image(1, spec_.width, rows, 1, native_.data() + offset, type,
                               static_cast<OIIO::stride_t>(pixel_bytes_), static_cast<OIIO::stride_t>(row_bytes_),
                               OIIO::AutoStride, out + c, OIIO::TypeDesc::FLOAT,
                               static_cast<OIIO::stride_t>(sizeof(float)) * spec_.nchannels,
                               static_cast<OIIO::stride_t>(sizeof(float) * values), OIIO::AutoStride))
        return false;
      offset += type.size();
    }
    return true;
  }

  OIIO::ImageInput& input_;
  const OIIO::ImageSpec& spec_;
  const SourceLocation& where_;
  std::size_t pixel_bytes_, row_bytes_;
  bool row_by_row_;
  std::vector<unsigned char> native_, tile_;
};

}  // namespace

void write_image(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options) {
  if (write_without_openimageio(file, image, options)) return;
  const bool any_channel_count = writer_for(file)->supports("nchannels");
  require_writable_image(file, image);
  OIIO::ImageSpec spec;
  const PixelEncoding encoding = encoding_for(file);
  PixelBuffer pixels;
  if (encoding == PixelEncoding::kSceneLinearFloat) {
    describe_scene_linear(spec, image, any_channel_count, options);
    pixels = scene_linear_channels(image, spec.nchannels);
  } else {
    pixels = encode_display_referred(spec, image, encoding, options);
  }
  write_pixels(file, spec, pixels);
}

Image read_image(const std::filesystem::path& file, std::uint64_t max_bytes) {
  if (std::optional<Image> image = read_exr_without_openimageio(file, max_bytes)) return std::move(*image);
  return read_image_counting(file, max_bytes, 0, "");
}

Image read_image_counting(const std::filesystem::path& file, std::uint64_t max_bytes,
                          std::uint64_t extra_bytes_per_pixel, const std::string& extra_purpose) {
  const SourceLocation where{file.string()};
  require_image_file(file);
  // The caller's budget (render's --max-memory or its default) or, without one, the default here.
  const std::string budget =
      max_bytes == 0 ? " (the smaller of " + format_bytes(kDefaultMemoryBudgetCap) + " and the available memory)"
                     : " (the memory budget)";
  if (max_bytes == 0) max_bytes = default_memory_budget();
  // A small hostile header can declare an enormous image: its size is checked before the library
  // allocates for it (at open for OpenEXR, whose declared size the header check returns) and
  // again from the opened spec.
  const auto refuse_if_too_large = [&](std::uint64_t width, std::uint64_t height, std::uint64_t channels,
                                       std::uint64_t tile_pixels = 0) {
    if (image_read_allowed(width, height, channels, tile_pixels, extra_bytes_per_pixel, max_bytes)) return;
    throw InputError(
        where, "the image is too large to read: " + std::to_string(width) + "x" + std::to_string(height) + ", " +
                   std::to_string(channels) + " channels" +
                   (tile_pixels > width * height ? " in tiles of " + std::to_string(tile_pixels) + " pixels" : "") +
                   " is " +
                   format_bytes(image_read_bytes(width, height, channels, tile_pixels, extra_bytes_per_pixel)) +
                   " as floats" + (extra_bytes_per_pixel ? " " + extra_purpose : std::string()) + "; the limit is " +
                   format_bytes(max_bytes) + budget);
  };
  if (const auto declared = check_image_header(file))
    refuse_if_too_large(declared->width, declared->height, declared->channels,
                        saturating_multiply(declared->tile_width, declared->tile_height));
  // One reader, chosen by signature or extension (image_format_sniff.h); OpenImageIO's fallback
  // to every reader it has is never taken.
  const std::string reader = image_reader_name(file);
  if (reader.empty())
    throw InputError(where, "cannot tell what kind of image this is: it has no extension and no signature rtpro knows");
  const auto input = OIIO::ImageInput::create(reader, /*do_open=*/false);
  if (!input)
    throw InputError(where, "cannot read image: no reader for '" + reader + "' images (" + oiio_errors("") + ")");
  // OpenImageIO's readers can throw from inside open and read (its BMP reader's RLE decoding at
  // open resized a vector to a corrupt file's size and threw std::length_error: a fuzz finding
  // that ended `rtpro compare` in std::terminate). Anything the library throws is this file's
  // fault: an input error naming it.
  const auto decode = [&]() -> Image {
    OIIO::ImageSpec opened_spec;
    if (!input->open(file.string(), opened_spec))
      throw InputError(
          where, "cannot read image as " + std::string(input->format_name()) + ": " + oiio_errors(input->geterror()));
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.deep || spec.depth > 1) throw InputError(where, "deep and volume images are not supported");
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throw InputError(where, "the image has no pixels");
    refuse_if_too_large(static_cast<std::uint64_t>(spec.width), static_cast<std::uint64_t>(spec.height),
                        static_cast<std::uint64_t>(spec.nchannels));
    // The data window is the image: an offset or a differing display window is not kept.
    // Pixels are decoded a band of rows at a time and the image grows as they arrive: the address
    // space is reserved once, but memory is touched only for rows that really decode, so a
    // 75-byte PPM declaring 100000x100 fails after one band instead of after clearing 120 MB.
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.channelnames;
    const std::size_t row_values = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.nchannels);
    image.data.reserve(row_values * static_cast<std::size_t>(spec.height));
    // A tiled image is read one row of tiles at a time.
    const bool tiled = spec.tile_width > 0;
    const std::size_t wanted_rows = image_read_band_rows(row_values);
    const int band_rows = static_cast<int>(
        std::min<std::size_t>(tiled ? static_cast<std::size_t>(std::max(spec.tile_height, 1)) : wanted_rows,
                              static_cast<std::size_t>(spec.height)));
    if (tiled) {
      const std::uint64_t tile_bytes =
          saturating_multiply(saturating_multiply(static_cast<std::uint64_t>(spec.tile_width),
                                                  static_cast<std::uint64_t>(std::max(spec.tile_height, 1))),
                              spec.pixel_bytes(/*native=*/true));
      if (tile_bytes > max_bytes)
        throw InputError(where, "the image's tiles are too large to read: " + std::to_string(spec.tile_width) + "x" +
                                    std::to_string(spec.tile_height) + " pixels, " + format_bytes(tile_bytes) +
                                    "; the limit is " + format_bytes(max_bytes));
    }
    NativeBands bands(*input, spec, band_rows, where);
    for (int y = 0; y < spec.height; y += band_rows) {
      const int end = std::min(y + band_rows, spec.height);
      image.data.resize(row_values * static_cast<std::size_t>(end));
      if (!bands.read(y, end, image.data.data() + row_values * static_cast<std::size_t>(y)))
        throw InputError(where, "cannot read image: " + oiio_errors(input->geterror()));
    }
    return image;
  };
  try {
    return decode();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& failure) {
    throw InputError(where, "the image library failed on this file: " + std::string(failure.what()));
  }
}

}  // namespace rtpro
