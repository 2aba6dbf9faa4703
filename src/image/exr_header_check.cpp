#include "exr_header_check.h"

#include "rtpro/core/error.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string>

namespace rtpro {

namespace {

constexpr std::uint8_t kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr std::uint32_t kMultipartFlag = 0x1000;
constexpr std::size_t kMaxNameBytes = 256;  // names and type names: 31 or 255 characters

// A null-terminated name; empty when the first byte is the terminator.
bool read_name(std::ifstream& in, std::string& name) {
  name.clear();
  for (char c; in.get(c);) {
    if (c == '\0') return true;
    if (name.size() == kMaxNameBytes) return false;
    name.push_back(c);
  }
  return false;
}

std::uint32_t read_u32(std::ifstream& in) {
  unsigned char b[4] = {};
  in.read(reinterpret_cast<char*>(b), 4);
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

}  // namespace

bool looks_like_exr(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char magic[4] = {};
  return in.read(reinterpret_cast<char*>(magic), 4) && std::equal(magic, magic + 4, kMagic);
}

void check_exr_header(const std::filesystem::path& file) {
  const SourceLocation where{file.string()};
  std::error_code error;
  const std::uintmax_t file_size = std::filesystem::file_size(file, error);
  std::ifstream in(file, std::ios::binary);
  if (error || !in) return;  // read_image reports unreadable files itself
  in.seekg(4);
  const bool multipart = (read_u32(in) & kMultipartFlag) != 0;
  const auto cut_short = [&] { throw InputError(where, "not a valid OpenEXR file: its header is cut short"); };
  std::string name, type;
  // One header, or for multi-part files a list of headers ended by an empty one.
  for (bool first_header = true;; first_header = false) {
    std::size_t attributes = 0;
    while (true) {
      if (!read_name(in, name)) cut_short();
      if (name.empty()) break;
      ++attributes;
      if (!read_name(in, type)) cut_short();
      const std::uint32_t size = read_u32(in);
      if (!in) cut_short();
      const auto position = static_cast<std::uintmax_t>(in.tellg());
      if (size > file_size - position)
        throw InputError(where, "not a valid OpenEXR file: attribute '" + name + "' claims " + std::to_string(size) +
                                    " bytes, more than the " + std::to_string(file_size - position) +
                                    " left in the file");
      in.seekg(size, std::ios::cur);
    }
    if (!multipart || (attributes == 0 && !first_header)) return;
  }
}

}  // namespace rtpro
