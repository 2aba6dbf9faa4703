#pragma once
// The PLY loader's readers of a body's values (ply_parser.cpp walks the elements with them): one
// for binary bodies, one for ASCII bodies; each names where a bad value is when it fails.
#include "ascii_scan.h"
#include "ply_header.h"
#include "rtpro/core/error.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace rtpro::ply {

// Whether an integer read from an ASCII body is in range for its property type.
inline bool fits(std::int64_t v, Type type) {
  switch (type) {
    case Type::kInt8: return v >= INT8_MIN && v <= INT8_MAX;
    case Type::kUInt8: return v >= 0 && v <= UINT8_MAX;
    case Type::kInt16: return v >= INT16_MIN && v <= INT16_MAX;
    case Type::kUInt16: return v >= 0 && v <= UINT16_MAX;
    case Type::kInt32: return v >= INT32_MIN && v <= INT32_MAX;
    case Type::kUInt32: return v >= 0 && v <= UINT32_MAX;
    case Type::kFloat32:
    case Type::kFloat64: return true;
  }
  return false;
}

// Reads the values of a binary body in order. Errors name the byte offset of the last value.
class BinaryReader {
 public:
  BinaryReader(std::string_view bytes, std::size_t offset, bool big_endian, const std::string& file)
      : bytes_(bytes), offset_(offset), swap_(big_endian != (std::endian::native == std::endian::big)), file_(file) {}

  void begin_element() {}
  void end_element() {}

  double value(Type type) {
    value_offset_ = offset_;
    const std::size_t size = size_of(type);
    if (bytes_.size() - offset_ < size) fail("the file ends before the data its header declares (truncated)");
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + offset_, size);
    if (swap_) std::reverse(raw, raw + size);
    offset_ += size;
    switch (type) {
      case Type::kInt8: return as<std::int8_t>(raw);
      case Type::kUInt8: return as<std::uint8_t>(raw);
      case Type::kInt16: return as<std::int16_t>(raw);
      case Type::kUInt16: return as<std::uint16_t>(raw);
      case Type::kInt32: return as<std::int32_t>(raw);
      case Type::kUInt32: return as<std::uint32_t>(raw);
      case Type::kFloat32: return finite(as<float>(raw));
      case Type::kFloat64: return finite(as<double>(raw));
    }
    return 0.0;
  }

  [[noreturn, gnu::cold, gnu::noinline]] void fail(const std::string& message) const {
    throw InputError(SourceLocation{file_}, message + " (at byte offset " + std::to_string(value_offset_) + ")");
  }

 private:
  template <typename T>
  static double as(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return double(value);
  }

  double finite(double value) const {
    if (!std::isfinite(value)) fail("value is not a finite number");
    return value;
  }

  std::string_view bytes_;
  std::size_t offset_;
  std::size_t value_offset_ = 0;
  bool swap_;
  const std::string& file_;
};

// Reads the values of an ASCII body: one element per line. Errors name line and column.
class AsciiReader {
 public:
  AsciiReader(std::string_view bytes, std::size_t offset, int first_line, const std::string& file)
      : next_(bytes.data() + offset), end_(bytes.data() + bytes.size()), line_(first_line - 1), file_(file) {}

  void begin_element() {
    do {
      if (next_ == end_) {
        ++line_;
        line_begin_ = value_ = end_;
        fail("the file ends before the elements its header declares");
      }
      line_begin_ = next_;
      line_end_ = ascii::find_line_end(next_, end_);
      next_ = line_end_ == end_ ? end_ : line_end_ + 1;
      ++line_;
      p_ = ascii::skip_blanks(line_begin_, line_end_);
    } while (p_ == line_end_);  // blank lines carry no element
  }

  void end_element() {
    p_ = ascii::skip_blanks(p_, line_end_);
    value_ = p_;
    if (p_ != line_end_)
      fail("unexpected " + ascii::quoted(ascii::word_at(p_, line_end_)) + ": more values than the header declares");
  }

  double value(Type type) {
    value_ = p_ = ascii::skip_blanks(p_, line_end_);
    if (p_ == line_end_) fail("too few values on this line for the header's properties");
    if (is_integer(type)) return integer(type);
    if (type == Type::kFloat32) return real<float>();
    return real<double>();
  }

  [[noreturn, gnu::cold, gnu::noinline]] void fail(const std::string& message) const {
    throw InputError(SourceLocation{file_, line_, int(value_ - line_begin_) + 1}, message);
  }

 private:
  double integer(Type type) {
    std::int64_t v = 0;
    const ascii::IntegerScan scan = ascii::scan_integer(p_, line_end_, v);
    if (!scan.ok || (scan.next != line_end_ && !ascii::is_blank(*scan.next)))
      fail(ascii::quoted(ascii::word_at(p_, line_end_)) + " is not an integer");
    if (!fits(v, type)) fail(ascii::quoted(ascii::word_at(p_, line_end_)) + " is out of range for its property type");
    p_ = scan.next;
    return double(v);
  }

  template <typename Real>
  double real() {
    Real v = 0;
    const ascii::FloatScan scan = ascii::scan_real(p_, line_end_, v);
    if (scan.status == ascii::NumberStatus::kMalformed)
      fail(ascii::quoted(ascii::word_at(p_, line_end_)) + " is not a number");
    if (scan.status == ascii::NumberStatus::kNotFinite)
      fail(ascii::quoted(ascii::word_at(p_, line_end_)) + " is not a finite number in range");
    p_ = scan.next;
    return double(v);
  }

  const char* next_;
  const char* end_;
  const char* line_begin_ = nullptr;
  const char* line_end_ = nullptr;
  const char* p_ = nullptr;
  const char* value_ = nullptr;
  int line_;
  const std::string& file_;
};

}  // namespace rtpro::ply
