// The one rule by which every value from a file or from gmsh is shown in a message
// (core/io/shown_text.h): one line, no control character, no terminal escape, valid UTF-8 kept.
#include <gtest/gtest.h>

#include <string>

#include "core/io/shown_text.h"

namespace {

using thinlayer::shown;

TEST(ShownText, PrintableTextAndUtf8AreKept) {
  EXPECT_EQ(shown("lap-joint 1.5 mm"), "lap-joint 1.5 mm");
  EXPECT_EQ(shown("\xce\xb5 \xe2\x89\xa4 0.1"), "\xce\xb5 \xe2\x89\xa4 0.1");  // "ε ≤ 0.1"
  EXPECT_EQ(shown("\xf0\x9f\x98\x80"), "\xf0\x9f\x98\x80");                    // U+1F600, four bytes
  EXPECT_EQ(shown("a\\b"), "a\\b");
}

TEST(ShownText, ControlCharactersAndTerminalEscapesAreEscaped) {
  EXPECT_EQ(shown("str\x1b[31mRED\nain"), "str\\u001b[31mRED\\u000aain");
  EXPECT_EQ(shown(std::string("a\0b", 3)), "a\\u0000b");
  EXPECT_EQ(shown("\r\t\x7f"), "\\u000d\\u0009\\u007f");
  EXPECT_EQ(shown("\xc2\x9b" "31m"), "\\u009b31m");              // C1 CSI, as UTF-8
  EXPECT_EQ(shown("\xc2\x85"), "\\u0085");                       // NEL
  EXPECT_EQ(shown("\xe2\x80\xa8\xe2\x80\xa9"), "\\u2028\\u2029");  // line, paragraph separators
  EXPECT_EQ(shown("\xe2\x80\xae" "cba"), "\\u202ecba");          // right-to-left override
  EXPECT_EQ(shown("\xe2\x81\xa6x"), "\\u2066x");                 // left-to-right isolate
}

TEST(ShownText, BytesThatAreNoUtf8AreShownAsBytes) {
  EXPECT_EQ(shown("\xff\xfe"), "\\xff\\xfe");
  EXPECT_EQ(shown("\x80"), "\\x80");                  // a continuation byte alone
  EXPECT_EQ(shown("\xc3"), "\\xc3");                  // a sequence cut short
  EXPECT_EQ(shown("\xc0\x8a"), "\\xc0\\x8a");         // an overlong newline
  EXPECT_EQ(shown("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  EXPECT_EQ(shown("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // beyond U+10FFFF
}

TEST(ShownText, TheResultIsOneLineWhateverTheBytes) {
  std::string every;
  for (int c = 0; c < 256; ++c) every.push_back(static_cast<char>(c));
  const std::string s = shown(every + every);
  for (unsigned char c : s) EXPECT_TRUE(c >= 0x20 && c != 0x7f) << static_cast<int>(c);
}

}  // namespace
