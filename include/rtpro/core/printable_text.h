#pragma once
// Text read from a file (a journal, another rank's message) shown in a message: an escape sequence,
// a carriage return or a newline in it must not reach the terminal raw, where it could rewrite or
// forge what rtpro prints.
#include <string>
#include <string_view>

namespace rtpro {

// `text` with control characters (C0, DEL, and C1 in UTF-8), backslashes and bytes that are not
// well-formed UTF-8 shown as \xNN; other UTF-8 unchanged.
std::string printable_text(std::string_view text);

}  // namespace rtpro
