#include "image_header_check.h"

#include "rtpro/core/error.h"

#include <algorithm>
#include <cstdint>
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

}  // namespace

void check_image_header(const std::filesystem::path& file) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return;  // read_image reports unreadable files itself
  Reader in(file, size);
  const SourceLocation where{file.string()};
  if (in.starts_with(kExrMagic, sizeof kExrMagic)) check_exr(in, where);
  else if (in.starts_with(kPngSignature, sizeof kPngSignature)) check_png(in, where);
}

}  // namespace rtpro
