#include "rtpro/core/printable_text.h"

namespace rtpro {

namespace {

// The length of the printable UTF-8 sequence starting text[0], or 0 (also for a backslash, unless
// `keep_backslash`).
std::size_t printable_sequence_length(std::string_view text, bool keep_backslash) {
  const auto lead = static_cast<unsigned char>(text[0]);
  if (lead < 0x20 || lead == 0x7f || (lead == '\\' && !keep_backslash)) return 0;
  const std::size_t length = utf8_sequence_length(text);
  // U+0080..U+009F are the C1 controls (U+009B is a terminal's CSI).
  if (length == 2 && lead == 0xc2 && static_cast<unsigned char>(text[1]) < 0xa0) return 0;
  return length;
}

std::string escaped(std::string_view shown, bool keep_backslash) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(shown.size());
  for (std::size_t i = 0; i < shown.size();) {
    if (const std::size_t length = printable_sequence_length(shown.substr(i), keep_backslash); length > 0) {
      out += shown.substr(i, length);
      i += length;
      continue;
    }
    const auto byte = static_cast<unsigned char>(shown[i++]);
    out += "\\x";
    out += kHex[byte >> 4];
    out += kHex[byte & 15];
  }
  return out;
}

}  // namespace

std::size_t utf8_sequence_length(std::string_view text) {
  const auto lead = static_cast<unsigned char>(text[0]);
  if (lead < 0x80) return 1;
  const std::size_t length = lead >= 0xc2 && lead <= 0xdf   ? 2
                             : lead >= 0xe0 && lead <= 0xef ? 3
                             : lead >= 0xf0 && lead <= 0xf4 ? 4
                                                            : 0;
  if (length == 0 || text.size() < length) return 0;
  for (std::size_t k = 1; k < length; ++k)
    if ((static_cast<unsigned char>(text[k]) & 0xc0) != 0x80) return 0;
  return length;
}

std::string printable_text(std::string_view text, std::size_t max_bytes) {
  return escaped(text.substr(0, max_bytes), false);
}

std::string printable_message(std::string_view text) { return escaped(text, true); }

}  // namespace rtpro
