#include "mesh_text_encoding.h"

#include "rtpro/core/error.h"

#include <algorithm>

namespace rtpro {

namespace {

bool starts_with(std::string_view bytes, std::string_view prefix) { return bytes.substr(0, prefix.size()) == prefix; }

}  // namespace

std::optional<std::string> wide_text_encoding(std::string_view bytes) {
  using namespace std::string_view_literals;
  // UTF-32 first: its little-endian mark begins with UTF-16's.
  if (starts_with(bytes, "\xFF\xFE\0\0"sv)) return "UTF-32 (little-endian)";
  if (starts_with(bytes, "\0\0\xFE\xFF"sv)) return "UTF-32 (big-endian)";
  if (starts_with(bytes, "\xFF\xFE"sv)) return "UTF-16 (little-endian)";
  if (starts_with(bytes, "\xFE\xFF"sv)) return "UTF-16 (big-endian)";
  // Without a mark: ASCII text in UTF-16 has a NUL in every other byte, in UTF-32 three of four.
  // A text file proper has no NUL at all, so a few among its first bytes settle it.
  const std::string_view head = bytes.substr(0, 64);
  const auto nuls = std::count(head.begin(), head.end(), '\0');
  if (nuls == 0 || head.size() < 4) return std::nullopt;
  if (nuls * 4 >= std::ptrdiff_t(head.size()) * 3 - 4)
    return head[0] == '\0' ? "UTF-32 (big-endian)" : "UTF-32 (little-endian)";
  if (nuls * 2 >= std::ptrdiff_t(head.size()) - 2)
    return head[0] == '\0' ? "UTF-16 (big-endian)" : "UTF-16 (little-endian)";
  return std::nullopt;
}

void require_narrow_text(std::string_view bytes, const std::string& file, const char* format) {
  if (const std::optional<std::string> encoding = wide_text_encoding(bytes))
    throw InputError(SourceLocation{file}, "the file is encoded as " + *encoding + "; rtpro reads " + format +
                                               " files as ASCII or UTF-8 (convert it, e.g. iconv -f UTF-16 -t UTF-8)");
}

std::string_view without_utf8_bom(std::string_view bytes) {
  return starts_with(bytes, "\xEF\xBB\xBF") ? bytes.substr(3) : bytes;
}

}  // namespace rtpro
