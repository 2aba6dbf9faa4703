#include "png_output.h"

#include "display_encoding.h"
#include "image_metadata.h"
#include "pixel_encoding.h"
#include "rtpro/core/error.h"
#include "rtpro/image/atomic_file_replacement.h"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <strings.h>
#include <vector>

namespace rtpro {

namespace {

// What libpng is given: plain data, so that nothing in the frame libpng may longjmp out of has a
// destructor to run.
struct PngRequest {
  int width = 0, height = 0;
  const std::uint8_t* rgb = nullptr;  // width × height RGB triples, row by row
  bool srgb = false;
  const png_time* time = nullptr;
  const png_text* texts = nullptr;
  int text_count = 0;
};

// Where libpng's callbacks write: the file's bytes, or why libpng gave up.
struct PngSink {
  std::string* bytes = nullptr;
  char error[160] = {};
};

void append_bytes(png_structp png, png_bytep data, std::size_t length) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  bool appended = true;
  try {
    sink->bytes->append(reinterpret_cast<const char*>(data), length);
  } catch (...) {
    appended = false;
  }
  // Outside the try block: png_error longjmps, and must not leave a handler or destructor behind.
  if (!appended) png_error(png, "out of memory for the encoded file");
}

void flush_nothing(png_structp) {}

[[noreturn]] void record_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<PngSink*>(png_get_error_ptr(png));
  std::snprintf(sink->error, sizeof sink->error, "%s", message ? message : "unknown libpng error");
  png_longjmp(png, 1);
}

// libpng's warnings (a keyword it shortens) change nothing it writes.
void ignore_warning(png_structp, png_const_charp) {}

// Every libpng call of an encoding, between setjmp and this function's return: libpng reports an
// error by longjmp back to here. Returns false with sink.error set when libpng fails.
bool run_libpng(const PngRequest& request, PngSink& sink) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, record_error, ignore_warning);
  if (!png) {
    std::snprintf(sink.error, sizeof sink.error, "libpng cannot create a writer");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(sink.error, sizeof sink.error, "libpng cannot create a header");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &sink, append_bytes, flush_nothing);
  png_set_compression_level(png, 6);
  png_set_compression_strategy(png, Z_DEFAULT_STRATEGY);
  png_set_IHDR(png, info, static_cast<png_uint_32>(request.width), static_cast<png_uint_32>(request.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_oFFs(png, info, 0, 0, PNG_OFFSET_PIXEL);
  if (request.srgb) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
  if (request.time) png_set_tIME(png, info, request.time);
  if (request.text_count > 0) png_set_text(png, info, request.texts, request.text_count);
  png_write_info(png, info);
  const std::size_t row_bytes = static_cast<std::size_t>(request.width) * 3;
  for (int y = 0; y < request.height; ++y) png_write_row(png, request.rgb + static_cast<std::size_t>(y) * row_bytes);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// DateTime in its TIFF/EXIF form, "YYYY:MM:DD HH:MM:SS", as PNG's tIME; nothing for another form.
std::optional<png_time> modification_time(const std::string& date_time) {
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0;
  if (std::sscanf(date_time.c_str(), "%4d:%2d:%2d %2d:%2d:%2d", &year, &month, &day, &hour, &minute, &second) != 6)
    return std::nullopt;
  png_time time{};
  time.year = static_cast<png_uint_16>(year);
  time.month = static_cast<png_byte>(month);
  time.day = static_cast<png_byte>(day);
  time.hour = static_cast<png_byte>(hour);
  time.minute = static_cast<png_byte>(minute);
  time.second = static_cast<png_byte>(second);
  return time;
}

// OpenImageIO's names for what PNG's registered keywords say, as its PNG writer maps them.
const char* png_keyword(const std::string& name) {
  if (strcasecmp(name.c_str(), "Artist") == 0) return "Author";
  if (strcasecmp(name.c_str(), "DocumentName") == 0 || strcasecmp(name.c_str(), "name") == 0) return "Title";
  if (strcasecmp(name.c_str(), "ImageDescription") == 0 || strcasecmp(name.c_str(), "description") == 0)
    return "Description";
  return name.c_str();
}

}  // namespace

bool is_png_file(const std::filesystem::path& file) { return lowercase_extension(file) == ".png"; }

std::string encode_png(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options) {
  require_writable_image(file, image);
  const DisplayEncoding display = display_encoding(options);
  const std::vector<std::uint8_t> rgb = encode_for_display_8bit(image, display.transform);

  std::vector<std::pair<std::string, std::string>> entries;
  if (display.srgb) entries.emplace_back("oiio:ColorSpace", "sRGB");
  std::optional<png_time> time;
  for (auto& entry : image_metadata(display.description, options)) {
    if (strcasecmp(entry.first.c_str(), "DateTime") == 0) time = modification_time(entry.second);
    else entries.push_back(std::move(entry));
  }
  std::vector<png_text> texts;
  for (const auto& [name, value] : entries) {
    png_text text{};
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = const_cast<char*>(png_keyword(name));
    text.text = const_cast<char*>(value.c_str());
    text.text_length = value.size();
    texts.push_back(text);
  }

  PngRequest request;
  request.width = image.width;
  request.height = image.height;
  request.rgb = rgb.data();
  request.srgb = display.srgb;
  request.time = time ? &*time : nullptr;
  request.texts = texts.data();
  request.text_count = static_cast<int>(texts.size());
  std::string bytes;
  bytes.reserve(rgb.size() / 2 + 4096);
  PngSink sink;
  sink.bytes = &bytes;
  if (!run_libpng(request, sink)) throw RuntimeError("cannot write " + file.string() + ": " + sink.error);
  return bytes;
}

void write_png(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options) {
  check_replaceable(file);
  write_file_atomically(file, encode_png(file, image, options));
}

}  // namespace rtpro
