// Keeps deploy/puddle.1, the man page the package installs, equal to format_man_page(), which is made
// from the options --help shows; and checks the page is well-formed man(7).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "app/cli.hpp"
#include "support/test_support.hpp"

namespace puddle::app {
namespace {

bool has_line(const std::string& page, const std::string& line) {
    std::istringstream in(page);
    for (std::string l; std::getline(in, l);)
        if (l == line) return true;
    return false;
}

TEST(ManPage, MatchesTheCommandLine) {
    const std::string expected = format_man_page();
    const auto out = test::output_dir() / "puddle.1";
    std::ofstream(out, std::ios::binary) << expected;

    const std::string path = PUDDLE_SOURCE_DIR "/deploy/puddle.1";
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), expected) << path
                                    << " is out of date with the options in src/app/cli.cpp. How to fix: cp "
                                    << out.string() << " " << path;
}

TEST(ManPage, HasTheSectionsDebianExpects) {
    const std::string page = format_man_page();
    EXPECT_TRUE(page.starts_with(".TH PUDDLE 1 ")) << page.substr(0, 80);
    for (const char* section : {".SH NAME", ".SH SYNOPSIS", ".SH DESCRIPTION", ".SH OPTIONS", ".SH EXAMPLES",
                                ".SH EXIT STATUS", ".SH FILES", ".SH SEE ALSO"})
        EXPECT_TRUE(has_line(page, section)) << section;
    // whatis(1) and lexgrog read the NAME line as "name \- summary".
    EXPECT_TRUE(
        has_line(page, "puddle \\- rain falling on a puddle, a real\\-time display for digital signage"));
}

TEST(ManPage, DocumentsEveryOptionAndExitCode) {
    const std::string page = format_man_page();
    for (const char* option :
         {"\\fB\\-c\\fR, \\fB\\-\\-config\\fR \\fIFILE\\fR", "\\fB\\-\\-stats\\fR [\\fISECONDS\\fR]",
          "\\fB\\-\\-check\\fR", "\\fB\\-b\\fR, \\fB\\-\\-backend\\fR \\fIKIND\\fR", "\\fB\\-\\-version\\fR"})
        EXPECT_TRUE(has_line(page, option)) << option;
    for (int code = 0; code <= 5; ++code) EXPECT_TRUE(has_line(page, ".B " + std::to_string(code))) << code;
}

// Only macros start a line with '.' or '\''; text that does must be guarded, or groff eats the line.
TEST(ManPage, TextNeverStartsWithAControlCharacter) {
    std::istringstream in(format_man_page());
    for (std::string l; std::getline(in, l);) {
        if (l.empty() || (l[0] != '.' && l[0] != '\'')) continue;
        const std::string macro = l.substr(0, l.find(' '));
        EXPECT_TRUE(macro == ".TH" || macro == ".SH" || macro == ".TP" || macro == ".B" || macro == ".I" ||
                    macro == ".PP")
            << l;
    }
}

}  // namespace
}  // namespace puddle::app
