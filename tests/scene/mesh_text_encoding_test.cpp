#include "ascii_scan.h"
#include "mesh_text_encoding.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace mesh_text_encoding_test {

using namespace std::string_literals;

TEST(TextEncoding, ByteOrderMarksAndNulPatternsAreRecognised) {
  EXPECT_EQ(wide_text_encoding("\xFF\xFEv\0"s), "UTF-16 (little-endian)");
  EXPECT_EQ(wide_text_encoding("\xFE\xFF\0v"s), "UTF-16 (big-endian)");
  EXPECT_EQ(wide_text_encoding("\xFF\xFE\0\0v\0\0\0"s), "UTF-32 (little-endian)");
  EXPECT_EQ(wide_text_encoding("\0\0\xFE\xFF\0\0\0v"s), "UTF-32 (big-endian)");
  EXPECT_EQ(wide_text_encoding("v\0 \0\x31\0 \0\x32\0"s), "UTF-16 (little-endian)");
  EXPECT_EQ(wide_text_encoding("\0v\0 \0\x31\0 \0\x32"s), "UTF-16 (big-endian)");
  EXPECT_EQ(wide_text_encoding("v\0\0\0 \0\0\0\x31\0\0\0"s), "UTF-32 (little-endian)");
  EXPECT_EQ(wide_text_encoding("v 1 2 3\nf 1 2 3\n"), std::nullopt);
  EXPECT_EQ(wide_text_encoding("\xEF\xBB\xBFv 1 2 3\n"), std::nullopt);  // UTF-8 with a mark is fine
  EXPECT_EQ(without_utf8_bom("\xEF\xBB\xBFv 1"), "v 1");
}

TEST(QuotedWords, ControlBytesAreEscapedAndLongWordsCut) {
  EXPECT_EQ(ascii::quoted("usemtl"), "'usemtl'");
  EXPECT_EQ(ascii::quoted("a\0b\x1b"s), "'a\\x00b\\x1b'");
  EXPECT_EQ(ascii::quoted("caf\xC3\xA9"), "'caf\xC3\xA9'");  // well-formed UTF-8 shown as it is
  EXPECT_EQ(ascii::quoted("caf\xC3"), "'caf\\xc3'");         // a cut sequence is not
  EXPECT_EQ(ascii::quoted("back\\slash"), "'back\\x5cslash'");
  const std::string quoted = ascii::quoted(std::string(1000, 'x'));
  EXPECT_EQ(quoted, "'" + std::string(ascii::kMaxQuotedBytes, 'x') + "' (cut: 1000 bytes)");
}

}  // namespace mesh_text_encoding_test
}  // namespace rtpro
