#include "image_header_check.h"

#include "rtpro/core/error.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

namespace rtpro {

namespace {

constexpr unsigned char kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
constexpr std::uint32_t kExrLongNames = 0x400;
constexpr std::uint32_t kExrMultipart = 0x1000;

class Reader {
 public:
  Reader(const std::filesystem::path& file, std::uintmax_t size) : in_(file, std::ios::binary), size_(size) {}
  bool ok() const { return static_cast<bool>(in_); }
  std::uintmax_t left() { return size_ - static_cast<std::uintmax_t>(in_.tellg()); }
  void skip(std::uintmax_t bytes) { in_.seekg(static_cast<std::streamoff>(bytes), std::ios::cur); }
  bool starts_with(const unsigned char* bytes, std::size_t count) {
    in_.seekg(0);
    std::string head(count, '\0');
    return in_.read(head.data(), static_cast<std::streamsize>(count)) && std::equal(bytes, bytes + count, head.begin(),
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
  std::string chars(std::size_t count) {
    std::string text(count, '\0');
    in_.read(text.data(), static_cast<std::streamsize>(count));
    return text;
  }

 private:
  std::ifstream in_;
  std::uintmax_t size_;
};

// OpenEXR reads names of at most 31 characters (255 with the long-names flag) and silently
// truncates longer ones, reading the rest as the type and size: refusing them keeps this walk
// and OpenEXR's in step.
void check_exr(Reader& in, const SourceLocation& where) {
  in.skip(0);
  const std::uint32_t flags = in.u32(false);
  const std::size_t max_name = (flags & kExrLongNames) ? 255 : 31;
  const auto bad = [&](const std::string& why) { throw InputError(where, "not a valid OpenEXR file: " + why); };
  std::string name, type;
  for (bool first = true;; first = false) {
    std::size_t attributes = 0;
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
      in.skip(size);
    }
    if (!(flags & kExrMultipart) || (attributes == 0 && !first)) return;
  }
}

void check_png(Reader& in, const SourceLocation& where) {
  while (in.left() > 0) {
    const std::uint32_t length = in.u32(true);
    const std::string type = in.chars(4);
    if (!in.ok()) return;  // a cut-short chunk list is libpng's to report; it allocates nothing
    if (std::uintmax_t(length) + 4 > in.left())
      throw InputError(where, "not a valid PNG file: chunk '" + type + "' claims " + std::to_string(length) +
                                  " bytes, more than the " + std::to_string(in.left()) + " left in the file");
    if (type == "IEND") return;
    in.skip(std::uintmax_t(length) + 4);  // data and CRC
  }
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
  if (width > 0 && height > 0 &&
      (width > data || height > data || width * height > data / (sample_bytes * channels)))
    throw InputError(where, "not a valid " + std::string(float_map ? "PFM" : "PNM") + " file: its header declares " +
                                std::to_string(width) + "x" + std::to_string(height) + " pixels, more than the " +
                                std::to_string(data) + " bytes of data hold");
}

}  // namespace

void check_image_header(const std::filesystem::path& file) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return;  // read_image reports unreadable files itself
  Reader in(file, size);
  const SourceLocation where{file.string()};
  if (in.starts_with(kExrMagic, sizeof kExrMagic)) check_exr(in, where);
  else if (in.starts_with(kPngSignature, sizeof kPngSignature)) check_png(in, where);
  else if (in.starts_with(reinterpret_cast<const unsigned char*>("P"), 1)) {
    in.skip(0);
    const std::string head = "P" + in.chars(static_cast<std::size_t>(std::min<std::uintmax_t>(size - 1, 255)));
    if (head.size() > 2 && (head[1] == '5' || head[1] == '6' || head[1] == 'F' || head[1] == 'f') &&
        std::isspace(static_cast<unsigned char>(head[2])) && head.find('#') == std::string::npos)
      check_raw_pnm(head, size, where);
  }
}

}  // namespace rtpro
