#include "ply_header.h"

#include "rtpro/core/error.h"
#include "ascii_scan.h"

#include <array>
#include <utility>

namespace rtpro::ply {

namespace {

constexpr std::array<std::pair<std::string_view, Type>, 16> kTypeNames{{
    {"char", Type::kInt8},
    {"int8", Type::kInt8},
    {"uchar", Type::kUInt8},
    {"uint8", Type::kUInt8},
    {"short", Type::kInt16},
    {"int16", Type::kInt16},
    {"ushort", Type::kUInt16},
    {"uint16", Type::kUInt16},
    {"int", Type::kInt32},
    {"int32", Type::kInt32},
    {"uint", Type::kUInt32},
    {"uint32", Type::kUInt32},
    {"float", Type::kFloat32},
    {"float32", Type::kFloat32},
    {"double", Type::kFloat64},
    {"float64", Type::kFloat64},
}};

class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  Header parse() {
    if (next_line() != "ply") fail("not a PLY file: the first line must be 'ply'");
    for (;;) {
      if (offset_ >= bytes_.size()) fail("the header has no end_header line");
      words_ = split(next_line());
      if (words_.empty() || words_[0] == "comment" || words_[0] == "obj_info") continue;
      if (words_[0] == "end_header") break;
      if (words_[0] == "format") read_format();
      else if (words_[0] == "element") read_element();
      else if (words_[0] == "property") read_property();
      else note_unknown_line();
    }
    if (!has_format_) fail("the header has no format line");
    if (unknown_lines_ > 0)
      header_.warnings.push_back(file_ + ":" + std::to_string(first_unknown_line_) + ": ignored " +
                                 std::to_string(unknown_lines_) + " unknown header line(s), the first starting " +
                                 ascii::quoted(first_unknown_word_));
    header_.body_offset = offset_;
    header_.body_line = line_ + 1;
    check_counts_fit();
    return std::move(header_);
  }

 private:
  std::string_view next_line() {
    const std::size_t newline = bytes_.find('\n', offset_);
    const std::size_t end = newline == std::string_view::npos ? bytes_.size() : newline;
    std::string_view line = bytes_.substr(offset_, end - offset_);
    offset_ = newline == std::string_view::npos ? bytes_.size() : newline + 1;
    ++line_;
    while (!line.empty() && ascii::is_blank(line.back())) line.remove_suffix(1);
    return line;
  }

  static std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> words;
    const char* p = line.data();
    const char* end = p + line.size();
    for (p = ascii::skip_blanks(p, end); p != end; p = ascii::skip_blanks(p, end)) {
      words.push_back(ascii::word_at(p, end));
      p += words.back().size();
    }
    return words;
  }

  void note_unknown_line() {
    if (unknown_lines_++ > 0) return;
    first_unknown_line_ = line_;
    first_unknown_word_ = std::string(words_[0]);
  }

  void read_format() {
    expect_words(3, "format <ascii|binary_little_endian|binary_big_endian> 1.0");
    if (words_[1] == "ascii") header_.encoding = Encoding::kAscii;
    else if (words_[1] == "binary_little_endian") header_.encoding = Encoding::kBinaryLittleEndian;
    else if (words_[1] == "binary_big_endian") header_.encoding = Encoding::kBinaryBigEndian;
    else fail("unknown format " + ascii::quoted(words_[1]));
    if (words_[2] != "1.0") fail("unsupported PLY version " + ascii::quoted(words_[2]));
    has_format_ = true;
  }

  void read_element() {
    expect_words(3, "element <name> <count>");
    std::int64_t count = 0;
    const ascii::IntegerScan scan = ascii::scan_integer(words_[2].data(), words_[2].data() + words_[2].size(), count);
    if (!scan.ok || scan.next != words_[2].data() + words_[2].size() || count < 0)
      fail("element count " + ascii::quoted(words_[2]) + " is not a non-negative integer");
    header_.elements.push_back({std::string(words_[1]), std::uint64_t(count), {}, line_});
  }

  void read_property() {
    if (header_.elements.empty()) fail("property before any element");
    Property property;
    if (words_.size() > 1 && words_[1] == "list") {
      expect_words(5, "property list <count type> <item type> <name>");
      property.is_list = true;
      property.count_type = type(words_[2]);
      if (!is_integer(property.count_type)) fail("a list's count type must be an integer type");
      property.type = type(words_[3]);
    } else {
      expect_words(3, "property <type> <name>");
      property.type = type(words_[1]);
    }
    property.name = std::string(words_.back());
    header_.elements.back().properties.push_back(std::move(property));
  }

  Type type(std::string_view name) const {
    for (const auto& [known, type] : kTypeNames)
      if (known == name) return type;
    fail("unknown property type " + ascii::quoted(name));
  }

  void expect_words(std::size_t count, const char* form) const {
    if (words_.size() != count) fail(std::string("expected '") + form + "'");
  }

  // Every element needs some bytes per instance; the counts must fit in what follows the header.
  // Checked before allocating anything, without overflow: count > remaining / bytes.
  void check_counts_fit() const {
    std::uint64_t remaining = bytes_.size() - header_.body_offset;
    if (header_.encoding == Encoding::kAscii) ++remaining;  // the last line may lack its newline
    for (const Element& element : header_.elements) {
      std::uint64_t least = 0;  // bytes per instance, at the least
      for (const Property& p : element.properties)
        least += header_.encoding == Encoding::kAscii ? 2 : size_of(p.is_list ? p.count_type : p.type);
      if (element.count > 0 && least == 0)
        fail_at(element.line, "element " + ascii::quoted(element.name) + " has no properties");
      if (element.count > 0 && element.count > remaining / least)
        fail_at(element.line, "element " + ascii::quoted(element.name) + " declares " + std::to_string(element.count) +
                                  " instances, more than the " + std::to_string(bytes_.size() - header_.body_offset) +
                                  " bytes after the header can hold");
      remaining -= element.count * least;
    }
  }

  [[noreturn]] void fail(const std::string& message) const { fail_at(line_, message); }
  [[noreturn]] void fail_at(int line, const std::string& message) const {
    throw InputError(SourceLocation{file_, line}, message);
  }

  std::string_view bytes_;
  const std::string& file_;
  std::size_t offset_ = 0;
  int line_ = 0;
  std::vector<std::string_view> words_;
  bool has_format_ = false;
  std::size_t unknown_lines_ = 0;
  int first_unknown_line_ = 0;
  std::string first_unknown_word_;
  Header header_;
};

}  // namespace

std::size_t size_of(Type type) {
  switch (type) {
    case Type::kInt8:
    case Type::kUInt8: return 1;
    case Type::kInt16:
    case Type::kUInt16: return 2;
    case Type::kInt32:
    case Type::kUInt32:
    case Type::kFloat32: return 4;
    case Type::kFloat64: return 8;
  }
  return 0;
}

int Element::find(std::string_view property) const {
  for (std::size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property) return int(i);
  return -1;
}

Header parse_header(std::string_view bytes, const std::string& file) { return HeaderParser(bytes, file).parse(); }

}  // namespace rtpro::ply
