#include "params/toml_syntax_error.hpp"

#include <gtest/gtest.h>

namespace puddle::params {
namespace {

TEST(KeyAtLine, NamesTheKeyWithTheTableAboveIt) {
    const std::string text =
        "# a comment [not] = a header\n"
        "[rain]\n"
        "intensity = 1e400\n"
        "\"seed\" = 1  # quoted key\n"
        "[[knob]]\n"
        "kind = \"encoder\"\n"
        "rain.wind = 2\n"
        "  [ look ]  # spaced header\n"
        "vignette = 9\n";
    EXPECT_EQ(key_at_line(text, 1), "");
    EXPECT_EQ(key_at_line(text, 2), "");
    EXPECT_EQ(key_at_line(text, 3), "rain.intensity");
    EXPECT_EQ(key_at_line(text, 4), "rain.seed");
    EXPECT_EQ(key_at_line(text, 6), "knob.kind");
    EXPECT_EQ(key_at_line(text, 7), "knob.rain.wind");
    EXPECT_EQ(key_at_line(text, 9), "look.vignette");
    EXPECT_EQ(key_at_line(text, 99), "");
}

TEST(KeyAtLine, ATopLevelDottedKeyHasNoTable) {
    EXPECT_EQ(key_at_line("rain.seed = 0x1ffffffffffffffff", 1), "rain.seed");
    EXPECT_EQ(key_at_line("= 3\n", 1), "");
}

TEST(ExplainTomlError, ANumberPast64BitsForAParameterIsOutOfRange) {
    EXPECT_EQ(explain_toml_error("[rain]\nseed = 99999999999999999999\n", 2,
                                 "Error while parsing decimal integer: '99999999999999999999' is not "
                                 "representable in 64 bits"),
              "rain.seed = 99999999999999999999 is out of range: allowed an integer from 0 to 2147483647");
}

TEST(ExplainTomlError, OtherErrorsKeepTomlsWordsWithTheKeyAndNoControlCharacters) {
    EXPECT_EQ(explain_toml_error("[ground]\ncheckerboard = tru\n", 2,
                                 "Error while parsing boolean: expected 'true', saw 'tru\n'"),
              "ground.checkerboard: Error while parsing boolean: expected 'true', saw 'tru?'");
    // A text parameter is not a number: an overflow word in its error is toml++'s own.
    EXPECT_EQ(explain_toml_error("[render]\nmethod = 1e400\n", 2, "could not be interpreted as a value"),
              "render.method: could not be interpreted as a value");
    EXPECT_EQ(explain_toml_error("[rain\n", 1, "expected ']'"), "expected ']'");
}

}  // namespace
}  // namespace puddle::params
