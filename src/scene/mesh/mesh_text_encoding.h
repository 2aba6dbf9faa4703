#pragma once
// Mesh text formats (OBJ, MTL, ASCII PLY headers) are ASCII or UTF-8. Files saved as UTF-16 or
// UTF-32 (Windows editors do that) would otherwise read as lines of NUL-separated garbage: an
// empty mesh with a page of warnings.
#include <optional>
#include <string>
#include <string_view>

namespace rtpro {

// "UTF-16 (little-endian)" and the like when the bytes start with a UTF-16/32 byte order mark,
// or look like UTF-16/32 without one (NUL bytes among the first bytes of a text); else nothing.
std::optional<std::string> wide_text_encoding(std::string_view bytes);

// Throws InputError naming `file` when wide_text_encoding() finds one.
void require_narrow_text(std::string_view bytes, const std::string& file, const char* format);

// The bytes without a leading UTF-8 byte order mark.
std::string_view without_utf8_bom(std::string_view bytes);

}  // namespace rtpro
