// util/valid_utf8.hpp: what is valid UTF-8 is kept byte for byte; every byte that is not becomes U+FFFD.
#include "util/valid_utf8.hpp"

#include <gtest/gtest.h>

namespace puddle {
namespace {

constexpr const char* fffd = "\xEF\xBF\xBD";

TEST(ValidUtf8, ValidTextIsKeptAndEachBadByteBecomesOneReplacement) {
    for (const char* good : {"", "plain",
                             "SoC temperature \xC2\xB0"
                             "C",
                             "\xE6\x97\xA5\xE6\x9C\xAC", "\xF0\x9F\x8C\xA7 rain", "\xF4\x8F\xBF\xBF"})
        EXPECT_EQ(valid_utf8(good), good);
    const std::string r = fffd;
    EXPECT_EQ(valid_utf8("a\xFF\xFE"
                         "b"),
              "a" + r + r + "b");
    EXPECT_EQ(valid_utf8("\x80"), r) << "a stray continuation byte";
    EXPECT_EQ(valid_utf8("\xC0\xAF"), r + r) << "overlong '/'";
    EXPECT_EQ(valid_utf8("\xE0\x80\xAF"), r + r + r) << "overlong, three bytes";
    EXPECT_EQ(valid_utf8("\xED\xA0\x80"), r + r + r) << "a surrogate";
    EXPECT_EQ(valid_utf8("\xF4\x90\x80\x80"), r + r + r + r) << "beyond U+10FFFF";
    EXPECT_EQ(valid_utf8("x\xE2\x82"), "x" + r + r) << "truncated at the end";
    EXPECT_EQ(valid_utf8("\xE2\x82"
                         "A"),
              r + r + "A")
        << "truncated before ASCII";
    for (const char* bad : {"\xFF", "\xC0\xAF", "\xED\xA0\x80", "x\xE2\x82"}) {
        EXPECT_FALSE(is_valid_utf8(bad));
        EXPECT_TRUE(is_valid_utf8(valid_utf8(bad)));
    }
}

}  // namespace
}  // namespace puddle
