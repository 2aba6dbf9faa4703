#pragma once
// For the command-line tests: a string attribute of an EXR file's header (rtpro:spp, ...), read
// from the bytes without loading an image library into the test process.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

namespace rtpro::test {

// An EXR header attribute is its name, NUL, its type name, NUL, a 4-byte little-endian size and
// the value; a string attribute's value is its characters. Nothing when the file has no such
// string attribute.
inline std::optional<std::string> exr_string_attribute(const std::filesystem::path& file, const std::string& name) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key = std::string(name) + '\0' + "string" + '\0';
  const std::size_t at = bytes.find(key);
  if (at == std::string::npos || at + key.size() + 4 > bytes.size()) return std::nullopt;
  std::uint32_t size = 0;
  std::memcpy(&size, bytes.data() + at + key.size(), 4);
  if (at + key.size() + 4 + size > bytes.size()) return std::nullopt;
  return bytes.substr(at + key.size() + 4, size);
}

}  // namespace rtpro::test
