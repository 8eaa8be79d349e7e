#include "util/safe_quote.hpp"

#include <gtest/gtest.h>

namespace puddle {
namespace {

TEST(SafeQuote, ShortTextIsKeptAsItIs) {
    EXPECT_EQ(safe_quote("rain.intensity"), "rain.intensity");
    EXPECT_EQ(safe_quote(""), "");
    EXPECT_EQ(safe_quote(std::string(64, 'a')), std::string(64, 'a'));
}

TEST(SafeQuote, LongTextIsClippedAndSaysItsLength) {
    EXPECT_EQ(safe_quote(std::string(65, 'a')), std::string(64, 'a') + "... (65 bytes)");
    EXPECT_EQ(safe_quote("abcdef", 3), "abc... (6 bytes)");
}

TEST(SafeQuote, ControlCharactersCannotBreakTheLine) {
    EXPECT_EQ(safe_quote("a\nb\rc\x1b[2Jd\x7f"), "a?b?c?[2Jd?");
}

TEST(SafeQuote, AClipNeverSplitsAUtf8Character) {
    // "é" is two bytes (C3 A9): a limit between them cuts before it.
    EXPECT_EQ(safe_quote("ab\xC3\xA9z", 3), "ab... (5 bytes)");
    EXPECT_EQ(safe_quote("ab\xC3\xA9z", 4), "ab\xC3\xA9... (5 bytes)");
}

}  // namespace
}  // namespace puddle
