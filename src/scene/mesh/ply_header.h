#pragma once
// Internals of the PLY loader: the header, validated against the file's size before anything is
// allocated (a 200-byte file cannot hold 2^40 vertices).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro::ply {

enum class Type : std::uint8_t { kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kFloat32, kFloat64 };

std::size_t size_of(Type type);
inline bool is_integer(Type type) { return type != Type::kFloat32 && type != Type::kFloat64; }

struct Property {
  std::string name;
  Type type;  // of the value, or of each list item
  bool is_list = false;
  Type count_type = Type::kUInt8;  // of a list's length
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  int line = 0;  // of its "element" header line

  // Index of the property called `name`, or -1.
  int find(std::string_view property) const;
};

enum class Encoding { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct Header {
  Encoding encoding = Encoding::kAscii;
  std::vector<Element> elements;
  std::size_t body_offset = 0;        // the first byte after "end_header\n"
  int body_line = 0;                  // the line number of that byte
  std::vector<std::string> warnings;  // "file:line: ..." lines
};

// Throws InputError naming file:line for malformed headers and for element counts that the bytes
// after the header cannot hold. A line with an unknown keyword (old exporters wrote free text
// into the header) is a warning: it cannot change how the elements read.
Header parse_header(std::string_view bytes, const std::string& file);

}  // namespace rtpro::ply
