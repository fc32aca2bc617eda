#include "cosmems/scene/printable_text.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cosmems {
namespace {

TEST(PrintableTextTest, KeepsPrintableAsciiAndValidUtf8) {
  for (const std::string text : {"model.elements = 8", "d\xc3\xa9j\xc3\xa0", "\xe2\x82\xac 5",
                                 "\xf0\x9f\x98\x80", "no\xc2\xa0-break", "back\\slash"}) {
    EXPECT_EQ(PrintableText(text), text);
  }
}

TEST(PrintableTextTest, EscapesEveryControlCharacter) {
  EXPECT_EQ(PrintableText("a\nb\rc\td"), "a\\nb\\rc\\td");
  EXPECT_EQ(PrintableText(std::string("\x00\x1b[2J\x07\x7f", 7)), "\\x00\\x1B[2J\\x07\\x7F");
  // C1 controls: U+0085 (next line) and U+009B (control sequence introducer).
  EXPECT_EQ(PrintableText("\xc2\x85\xc2\x9b[31m"), "\\xC2\\x85\\xC2\\x9B[31m");
}

// Overlong forms, surrogates, code points past U+10FFFF, stray continuation bytes and truncated
// sequences are no UTF-8: each of their bytes is escaped, the valid text after them kept.
TEST(PrintableTextTest, EscapesInvalidUtf8ByteByByte) {
  EXPECT_EQ(PrintableText("\xc0\xaf"), "\\xC0\\xAF");
  EXPECT_EQ(PrintableText("\xe0\x80\xaf"), "\\xE0\\x80\\xAF");
  EXPECT_EQ(PrintableText("\xed\xa0\x80"), "\\xED\\xA0\\x80");
  EXPECT_EQ(PrintableText("\xf4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");
  EXPECT_EQ(PrintableText("\x80x"), "\\x80x");
  EXPECT_EQ(PrintableText("\xe2\x82"), "\\xE2\\x82");
  EXPECT_EQ(PrintableText("\xe2\x82\xc3\xa9"), "\\xE2\\x82\xc3\xa9");
}

TEST(PrintableTextTest, EscapingTwiceChangesNothingMore) {
  const std::string once = PrintableText("a\x1b\n\xff\xc2\x9b\xc3\xa9");
  EXPECT_EQ(PrintableText(once), once);
}

}  // namespace
}  // namespace cosmems
