#include "rtpro/core/printable_text.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace printable_text_test {

using namespace std::string_literals;

TEST(PrintableText, ControlsBackslashesAndBrokenUtf8AreEscaped) {
  EXPECT_EQ(printable_text("plain text"), "plain text");
  EXPECT_EQ(printable_text("a\0b\x1b[2J\r\n\x7f"s), "a\\x00b\\x1b[2J\\x0d\\x0a\\x7f");
  EXPECT_EQ(printable_text("back\\slash"), "back\\x5cslash");  // so an escape cannot be forged
  EXPECT_EQ(printable_text("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x99\x82"), "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x99\x82");
  EXPECT_EQ(printable_text("caf\xC3"), "caf\\xc3");                         // a cut sequence
  EXPECT_EQ(printable_text("\xC3(\x80\xC0\xAF"), "\\xc3(\\x80\\xc0\\xaf");  // broken, stray, never a lead
  EXPECT_EQ(printable_text("\xC2\x9B"
                           "2J \xC2\xA0"),
            "\\xc2\\x9b2J \xC2\xA0");  // C1's CSI, then U+00A0
}

TEST(PrintableText, IsCutAfterMaxBytesBeforeEscaping) {
  EXPECT_EQ(printable_text("abcdef", 3), "abc");
  EXPECT_EQ(printable_text("\x1b\x1b\x1b", 2), "\\x1b\\x1b");
  EXPECT_EQ(printable_text("ab\xC3\xA9", 3), "ab\\xc3");  // a sequence the cut splits is escaped
}

TEST(Utf8SequenceLength, CountsWellFormedSequencesOnly) {
  EXPECT_EQ(utf8_sequence_length("a"), 1u);
  EXPECT_EQ(utf8_sequence_length("\x01"), 1u);  // ASCII, controls too
  EXPECT_EQ(utf8_sequence_length("\xC3\xA9z"), 2u);
  EXPECT_EQ(utf8_sequence_length("\xE2\x82\xAC"), 3u);
  EXPECT_EQ(utf8_sequence_length("\xF0\x9F\x99\x82"), 4u);
  EXPECT_EQ(utf8_sequence_length("\xE2\x82"), 0u);          // cut short
  EXPECT_EQ(utf8_sequence_length("\xE2(\xAC"), 0u);         // broken
  EXPECT_EQ(utf8_sequence_length("\xA9"), 0u);              // a continuation byte
  EXPECT_EQ(utf8_sequence_length("\xC0\xAF"), 0u);          // an overlong lead
  EXPECT_EQ(utf8_sequence_length("\xF5\x80\x80\x80"), 0u);  // beyond U+10FFFF
}

}  // namespace printable_text_test
}  // namespace rtpro
