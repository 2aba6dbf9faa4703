#include "image_header_check.h"

#include "image_file_check.h"
#include "rtpro/core/error.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <string>

namespace rtpro {

namespace {

constexpr unsigned char kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
// libjpeg needs only the start-of-image marker first; it skips any bytes before the next marker.
constexpr unsigned char kJpegSignature[2] = {0xFF, 0xD8};
// giflib compares only the first three bytes of GIF's six-byte signature (GIF_VERSION_POS): a
// "GIF00a" file named .gif opens as well as a GIF89a.
constexpr unsigned char kGifStamp[3] = {'G', 'I', 'F'};
constexpr std::size_t kGifSignatureBytes = 6;
constexpr std::uint32_t kExrLongNames = 0x400;
constexpr std::uint32_t kExrMultipart = 0x1000;

class Reader {
 public:
  Reader(const std::filesystem::path& file, std::uintmax_t size) : in_(file, std::ios::binary), size_(size) {}
  bool ok() const { return static_cast<bool>(in_); }
  std::uintmax_t left() { return size_ - static_cast<std::uintmax_t>(in_.tellg()); }
  void skip(std::uintmax_t bytes) { in_.seekg(static_cast<std::streamoff>(bytes), std::ios::cur); }
  void seek(std::uintmax_t at) { in_.seekg(static_cast<std::streamoff>(at)); }
  bool starts_with(const unsigned char* bytes, std::size_t count) {
    in_.seekg(0);
    std::string head(count, '\0');
    return in_.read(head.data(), static_cast<std::streamsize>(count)) &&
           std::equal(bytes, bytes + count, head.begin(),
                      [](unsigned char a, char b) { return a == static_cast<unsigned char>(b); });
  }
  std::uint32_t u32(bool big_endian) {
    unsigned char b[4] = {};
    in_.read(reinterpret_cast<char*>(b), 4);
    return big_endian ? std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 | b[3]
                      : std::uint32_t(b[3]) << 24 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[1]) << 8 | b[0];
  }
  // A null-terminated name of at most `max` characters; false when longer or cut short.
  bool name(std::string& text, std::size_t max) {
    text.clear();
    for (char c; in_.get(c);) {
      if (c == '\0') return true;
      if (text.size() == max) return false;
      text.push_back(c);
    }
    return false;
  }
  std::int32_t i32() { return static_cast<std::int32_t>(u32(false)); }
  std::string chars(std::size_t count) {
    std::string text(count, '\0');
    in_.read(text.data(), static_cast<std::streamsize>(count));
    return text;
  }

 private:
  std::ifstream in_;
  std::uintmax_t size_;
};

// OpenEXR reads a known attribute type by its own layout, not by the size the file states: a
// box2i is 16 bytes whatever the size says, a channel list runs to its empty name, a preview holds
// the pixels its own width and height declare. A stated size that differs puts OpenEXR's reading
// of the rest of the header out of step with this walk (a fuzz finding: OpenEXR then read a 1.9 GB
// attribute size out of a channel name), so such files are refused.
std::optional<std::uint32_t> exr_fixed_size(const std::string& type) {
  static const std::map<std::string, std::uint32_t, std::less<>> kSizes = {{"box2i", 16},
                                                                           {"box2f", 16},
                                                                           {"chromaticities", 32},
                                                                           {"compression", 1},
                                                                           {"deepImageState", 1},
                                                                           {"double", 8},
                                                                           {"envmap", 1},
                                                                           {"float", 4},
                                                                           {"int", 4},
                                                                           {"keycode", 28},
                                                                           {"lineOrder", 1},
                                                                           {"m33f", 36},
                                                                           {"m33d", 72},
                                                                           {"m44f", 64},
                                                                           {"m44d", 128},
                                                                           {"rational", 8},
                                                                           {"tiledesc", 9},
                                                                           {"timecode", 8},
                                                                           {"v2i", 8},
                                                                           {"v2f", 8},
                                                                           {"v2d", 16},
                                                                           {"v3i", 12},
                                                                           {"v3f", 12},
                                                                           {"v3d", 24}};
  const auto found = kSizes.find(type);
  if (found == kSizes.end()) return std::nullopt;
  return found->second;
}

// The channels of a chlist attribute's bytes (null-terminated names, each followed by 16 bytes of
// pixel type, linear flag, reserved bytes and sampling, the list ended by an empty name), or
// nothing when the list does not end exactly at the attribute's last byte.
std::optional<std::uint64_t> exr_channel_count(const std::string& list) {
  std::uint64_t channels = 0;
  for (std::size_t at = 0; at < list.size(); ++channels) {
    if (list[at] == '\0') return at + 1 == list.size() ? std::optional<std::uint64_t>(channels) : std::nullopt;
    const std::size_t end = list.find('\0', at);
    if (end == std::string::npos) return std::nullopt;
    at = end + 1 + 16;
  }
  return std::nullopt;
}

std::uint32_t little_endian_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  return value;
}

DeclaredImageSize exr_declared_size(std::int64_t x_min, std::int64_t y_min, std::int64_t x_max, std::int64_t y_max,
                                    std::uint64_t channels) {
  DeclaredImageSize size;
  size.channels = channels;  // the tile buffers cost per channel even for an empty window
  if (x_max < x_min || y_max < y_min) return size;
  size.width = static_cast<std::uint64_t>(x_max - x_min + 1);
  size.height = static_cast<std::uint64_t>(y_max - y_min + 1);
  size.channels = channels;
  return size;
}

// OpenEXR reads names of at most 31 characters (255 with the long-names flag) and silently
// truncates longer ones, reading the rest as the type and size: refusing them keeps this walk
// and OpenEXR's in step.
std::optional<DeclaredImageSize> check_exr(Reader& in, const SourceLocation& where) {
  in.skip(0);
  const std::uint32_t flags = in.u32(false);
  const std::size_t max_name = (flags & kExrLongNames) ? 255 : 31;
  const auto bad = [&](const std::string& why) { throw InputError(where, "not a valid OpenEXR file: " + why); };
  DeclaredImageSize declared;
  std::string name, type;
  for (bool first = true;; first = false) {
    std::size_t attributes = 0;
    std::int64_t window[4] = {0, 0, -1, -1};
    bool has_window = false;
    std::uint64_t channels = 0, tile_width = 0, tile_height = 0;
    while (true) {
      if (!in.name(name, max_name)) bad("an attribute name is too long or the header is cut short");
      if (name.empty()) break;
      ++attributes;
      if (!in.name(type, max_name)) bad("attribute '" + name + "' has a bad type name");
      const std::uint32_t size = in.u32(false);
      if (!in.ok()) bad("the header is cut short");
      if (size > in.left())
        bad("attribute '" + name + "' claims " + std::to_string(size) + " bytes, more than the " +
            std::to_string(in.left()) + " left in the file");
      const auto out_of_step = [&] {
        bad("attribute '" + name + "' of type " + type + " states " + std::to_string(size) +
            " bytes, which its contents do not fill exactly");
      };
      if (const auto fixed = exr_fixed_size(type); fixed && *fixed != size) out_of_step();
      if (name == "dataWindow" && type == "box2i") {
        for (std::int64_t& bound : window) bound = in.i32();
        has_window = true;
      } else if (name == "tiles" && type == "tiledesc") {
        tile_width = in.u32(false);
        tile_height = in.u32(false);
        in.skip(1);  // level and rounding modes
      } else if (type == "chlist") {
        const auto count = exr_channel_count(in.chars(size));  // size is at most the bytes left
        if (!count) out_of_step();
        if (name == "channels") channels = *count;
      } else if (type == "preview") {
        const std::string preview = in.chars(size);
        if (size < 8 || std::uint64_t{little_endian_u32(preview, 0)} * little_endian_u32(preview, 4) * 4 != size - 8)
          out_of_step();
      } else if (type == "idmanifest") {
        // Its value is a compressed table whose stated uncompressed size is allocated before it is
        // checked; rtpro reads no ID manifests.
        bad("attribute '" + name + "' is an ID manifest, which rtpro does not read");
      } else {
        in.skip(size);
      }
    }
    // A header without its data window is not an OpenEXR file; OpenEXR would take a default
    // window of its own and size the tile buffers from the tile description alone, which this
    // walk would then not have counted (a fuzz finding: 1.6 GB at open for 777 bytes).
    if (attributes > 0 && !has_window) bad("a header has no dataWindow attribute of type box2i");
    if (first) {
      declared = exr_declared_size(window[0], window[1], window[2], window[3], channels);
      declared.tile_width = tile_width;
      declared.tile_height = tile_height;
    }
    if (!(flags & kExrMultipart) || (attributes == 0 && !first)) return declared;
  }
}

// Returns the size IHDR declares: OpenImageIO's PNG reader decodes the whole image when it opens
// the file, so a texture's budget must be checked from it before that.
std::optional<DeclaredImageSize> check_png(Reader& in, const SourceLocation& where) {
  std::optional<DeclaredImageSize> declared;
  while (in.left() > 0) {
    const std::uint32_t length = in.u32(true);
    const std::string type = in.chars(4);
    if (!in.ok()) return declared;  // a cut-short chunk list is libpng's to report; it allocates nothing
    if (std::uintmax_t(length) + 4 > in.left())
      throw InputError(where, "not a valid PNG file: chunk '" + type + "' claims " + std::to_string(length) +
                                  " bytes, more than the " + std::to_string(in.left()) + " left in the file");
    if (type == "IEND") return declared;
    if (type == "IHDR" && length >= 13 && !declared) {
      DeclaredImageSize size;
      size.width = in.u32(true);
      size.height = in.u32(true);
      const std::string depth_and_colour = in.chars(2);
      if (!in.ok()) return declared;
      // Grey, RGB, palette (read as RGB or RGBA), grey-alpha, RGBA.
      const int colour_type = static_cast<unsigned char>(depth_and_colour[1]);
      size.channels = colour_type == 0 ? 1 : colour_type == 4 ? 2 : colour_type == 2 ? 3 : 4;
      declared = size;
      in.skip(std::uintmax_t(length) - 10 + 4);  // the rest and the CRC
      continue;
    }
    in.skip(std::uintmax_t(length) + 4);  // data and CRC
  }
  return declared;
}

// OpenImageIO 2.4's JPEG reader decodes a Photoshop IPTC block in an APP13 segment ("Photoshop 3.0",
// a NUL, "8BIM", resource 0x0404, four bytes, a 2-byte size, then the records) by the size the
// block states, not by the bytes libjpeg saved for the segment: a 1,123-byte file whose block
// claimed 116 bytes in a segment of 89 made it read 111 bytes past its buffer while opening (a fuzz
// finding; ASan: heap-buffer-overflow in decode_iptc_iim). Its strcmp and strncmp of the block's
// start also read past a segment too short for them. The markers before the first scan (those
// libjpeg saves while reading the header) are walked, each APP13 segment is checked the way the
// reader will read it, byte for byte, and one it would read past is refused.
void check_jpeg_photoshop_block(const std::string& block, const SourceLocation& where) {
  const auto refuse = [&](const std::string& why) {
    throw InputError(where, "not a valid JPEG file: its Photoshop IPTC block (APP13 segment of " +
                                std::to_string(block.size()) + " bytes) " + why);
  };
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(block[i]); };
  constexpr char kSignature[] =
      "Photoshop 3.0\0"
      "8BIM";  // compared up to the first difference
  for (std::size_t i = 0; i < sizeof kSignature - 1; ++i) {
    if (i >= block.size()) refuse("ends inside its signature");
    if (block[i] != kSignature[i]) return;  // not an IPTC block: the reader stops here
  }
  constexpr std::size_t kType = 18, kSize = 24, kRecords = 26;
  if (block.size() < kType + 2) refuse("ends before its resource type");
  if ((byte(kType) << 8 | byte(kType + 1)) != 0x0404) return;  // not IPTC data
  if (block.size() < kRecords) refuse("ends before its size");
  const std::size_t size = static_cast<std::size_t>(byte(kSize) << 8 | byte(kSize + 1));
  if (size > block.size() - kRecords)
    refuse("claims " + std::to_string(size) + " bytes of records, more than the " +
           std::to_string(block.size() - kRecords) + " it holds");
}

void check_jpeg(Reader& in, const SourceLocation& where) {
  const auto u8 = [&] { return static_cast<unsigned char>(in.chars(1)[0]); };
  in.seek(2);  // after the start-of-image marker
  while (in.ok() && in.left() >= 2) {
    if (u8() != 0xFF) continue;  // libjpeg skips bytes before a marker (with a warning)
    unsigned char marker = u8();
    while (marker == 0xFF && in.ok() && in.left() > 0) marker = u8();    // fill bytes
    if (!in.ok() || marker == 0xD9 || marker == 0xDA) return;            // end of image, start of scan
    if (marker == 0x00) continue;                                        // a stuffed 0xFF byte, not a marker
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) continue;  // markers without a length
    if (in.left() < 2) return;
    const unsigned char high = u8(), low = u8();
    const std::uintmax_t length = std::uintmax_t(high) << 8 | low;
    if (length < 2) return;  // libjpeg refuses it
    if (marker != 0xED) {
      in.skip(length - 2);
      continue;
    }
    if (length - 2 > in.left())
      throw InputError(where, "not a valid JPEG file: an APP13 segment claims " + std::to_string(length - 2) +
                                  " bytes, more than the " + std::to_string(in.left()) + " left in the file");
    check_jpeg_photoshop_block(in.chars(static_cast<std::size_t>(length - 2)), where);
  }
}

// OpenImageIO's GIF reader allocates an RGBA canvas of the logical screen's size, and giflib a
// raster per frame, when the file is opened: a 30-byte GIF declaring 65535x65535 asked for 16 GiB
// (a fuzz finding). The largest of the screen and every frame is returned as the declared size.
// A block list cut short or malformed is left to giflib, which reports it.
DeclaredImageSize check_gif(Reader& in) {
  const auto u8 = [&] { return static_cast<unsigned char>(in.chars(1)[0]); };
  const auto u16 = [&] {
    const std::string b = in.chars(2);
    return static_cast<std::uint64_t>(static_cast<unsigned char>(b[0]) | static_cast<unsigned char>(b[1]) << 8);
  };
  const auto colour_table_bytes = [](unsigned char flags) {
    return (flags & 0x80) ? std::uintmax_t{3} << ((flags & 7) + 1) : std::uintmax_t{0};
  };
  const auto skip_sub_blocks = [&] {
    for (unsigned char length = u8(); in.ok() && length != 0; length = u8()) in.skip(length);
  };
  DeclaredImageSize declared;  // the signature has been read: the screen descriptor follows
  declared.channels = 4;
  declared.width = u16();
  declared.height = u16();
  const unsigned char screen_flags = u8();
  in.skip(2 + colour_table_bytes(screen_flags));
  while (in.ok() && in.left() > 0) {
    const unsigned char block = u8();
    if (block == 0x21) {  // extension: label, then data sub-blocks
      in.skip(1);
      skip_sub_blocks();
    } else if (block == 0x2c) {  // image descriptor: left, top, width, height, flags
      in.skip(4);
      declared.width = std::max(declared.width, u16());
      declared.height = std::max(declared.height, u16());
      in.skip(colour_table_bytes(u8()) + 1);  // local colour table, LZW code size
      skip_sub_blocks();
    } else {
      break;  // the trailer, or bytes giflib will refuse
    }
  }
  return declared;
}

// OpenImageIO's BMP reader decodes a run-length-encoded image whole when the file is opened, into a
// buffer of the declared width x height (a 118-byte file declaring 5x536870917 made it throw
// std::length_error at open; a smaller absurd height would allocate). The declared size is returned
// from the info header: Windows (40 bytes or more: signed 32-bit width and height, a negative height
// meaning top-down rows) or OS/2 core (12 bytes: unsigned 16-bit width and height).
DeclaredImageSize check_bmp(Reader& in) {
  DeclaredImageSize declared;  // the magic number has been read: file size, two reserved words, pixel offset
  in.skip(12);
  const std::uint32_t info_size = in.u32(false);
  if (info_size == 12) {
    const std::string b = in.chars(4);
    declared.width = static_cast<unsigned char>(b[0]) | static_cast<unsigned char>(b[1]) << 8;
    declared.height = static_cast<unsigned char>(b[2]) | static_cast<unsigned char>(b[3]) << 8;
  } else {
    declared.width = static_cast<std::uint64_t>(std::abs(static_cast<std::int64_t>(in.i32())));
    declared.height = static_cast<std::uint64_t>(std::abs(static_cast<std::int64_t>(in.i32())));
  }
  declared.channels = 4;  // at most RGBA
  return declared;
}

// Binary PNM (P5 grey, P6 RGB) and PFM (Pf grey, PF RGB) store raw samples: the header's size
// must fit in the bytes that follow it. Comments and odd whitespace are left to the reader.
void check_raw_pnm(const std::string& head, std::uintmax_t file_size, const SourceLocation& where) {
  const char kind = head[1];
  const bool float_map = kind == 'F' || kind == 'f';
  const int channels = (kind == '6' || kind == 'F') ? 3 : 1;
  unsigned long long width = 0, height = 0;
  double maxval = 0;
  int consumed = 0;
  const char* text = head.c_str() + 2;
  if (std::sscanf(text, "%llu %llu %lf%n", &width, &height, &maxval, &consumed) != 3) return;
  const std::uintmax_t sample_bytes = float_map ? 4 : (maxval > 255 ? 2 : 1);
  const std::uintmax_t header_bytes = 2 + static_cast<std::uintmax_t>(consumed) + 1;
  const std::uintmax_t data = file_size > header_bytes ? file_size - header_bytes : 0;
  if (width > 0 && height > 0 && (width > data || height > data || width * height > data / (sample_bytes * channels)))
    throw InputError(where, "not a valid " + std::string(float_map ? "PFM" : "PNM") + " file: its header declares " +
                                std::to_string(width) + "x" + std::to_string(height) + " pixels, more than the " +
                                std::to_string(data) + " bytes of data hold");
}

}  // namespace

std::optional<DeclaredImageSize> check_image_header(const std::filesystem::path& file) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return std::nullopt;  // read_image reports unreadable files itself
  Reader in(file, size);
  const SourceLocation where{file.string()};
  if (in.starts_with(kExrMagic, sizeof kExrMagic)) return check_exr(in, where);
  if (size >= kGifSignatureBytes && in.starts_with(kGifStamp, sizeof kGifStamp)) {
    in.seek(kGifSignatureBytes);
    return check_gif(in);
  }
  if (size >= 26) {
    // OpenImageIO's BMP reader takes OS/2's magic numbers as well as Windows' BM.
    in.seek(0);
    const std::string magic = in.chars(2);
    for (const char* bmp : {"BM", "BA", "CI", "CP", "PT"})
      if (magic == bmp) return check_bmp(in);
  }
  if (in.starts_with(kJpegSignature, sizeof kJpegSignature)) check_jpeg(in, where);
  else if (in.starts_with(kPngSignature, sizeof kPngSignature)) return check_png(in, where);
  else if (in.starts_with(reinterpret_cast<const unsigned char*>("P"), 1)) {
    in.skip(0);
    const std::string head = "P" + in.chars(static_cast<std::size_t>(std::min<std::uintmax_t>(size - 1, 255)));
    if (head.size() > 2 && (head[1] == '5' || head[1] == '6' || head[1] == 'F' || head[1] == 'f') &&
        std::isspace(static_cast<unsigned char>(head[2])) && head.find('#') == std::string::npos)
      check_raw_pnm(head, size, where);
  }
  return std::nullopt;
}

std::optional<ImageSize> image_size_from_header(const std::filesystem::path& file) {
  require_image_file(file);
  if (const auto declared = check_image_header(file))
    return ImageSize{declared->width, declared->height, declared->channels};
  return std::nullopt;
}

}  // namespace rtpro
