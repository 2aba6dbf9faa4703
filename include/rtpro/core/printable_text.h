#pragma once
// Text read from a file (a journal, another rank's message, a mesh or glTF file) shown in a
// message: an escape sequence, a carriage return or a newline in it must not reach the terminal
// raw, where it could rewrite or forge what rtpro prints.
#include <cstddef>
#include <string>
#include <string_view>

namespace rtpro {

// The first `max_bytes` bytes of `text` with control characters (C0, DEL, and C1 in UTF-8),
// backslashes and bytes that are not well-formed UTF-8 shown as \xNN; other UTF-8 unchanged. The
// cut keeps a 10 MB token from becoming a 10 MB message.
std::string printable_text(std::string_view text, std::size_t max_bytes = std::string_view::npos);

// A whole message as one line for the terminal: like printable_text, but backslashes stay as they
// are, so text printable_text already escaped is unchanged. rtpro's errors and log lines pass
// through it, so input echoed anywhere in them (a name, a key, a path, an option's value) can
// neither colour the terminal nor start a line of its own.
std::string printable_message(std::string_view text);

// The length of the UTF-8 sequence that starts the non-empty `text` (1 for ASCII), or 0 where none
// does: a byte that cannot lead one (a continuation byte, 0xc0, 0xc1, 0xf5 to 0xff) or a sequence cut short
// or broken by a byte that does not continue it.
std::size_t utf8_sequence_length(std::string_view text);

}  // namespace rtpro
