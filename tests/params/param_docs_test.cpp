// Keeps docs/parameters.md's parameter table equal to params::format_params_markdown(), so the
// documentation can never drift from params.def.
#include "params/param_docs.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace puddle::params {
namespace {

constexpr std::string_view begin_marker = "<!-- params:begin -->";
constexpr std::string_view end_marker = "<!-- params:end -->";

std::string_view without_cr(std::string_view line) {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
}

// The text between the marker lines, or an explanation of why there is none.
struct Section {
    bool found = false;
    std::string text;
    std::string problem;
};

Section find_section(const std::string& readme) {
    std::istringstream in(readme);
    std::string line;
    int begins = 0, ends = 0;
    bool inside = false;
    Section s;
    while (std::getline(in, line)) {
        const std::string_view l = without_cr(line);
        if (l == begin_marker) {
            ++begins;
            inside = true;
            continue;
        }
        if (l == end_marker) {
            ++ends;
            if (!inside) return {false, "", fmt::format("'{}' comes before '{}'", end_marker, begin_marker)};
            inside = false;
            continue;
        }
        if (inside) s.text += line + "\n";
    }
    if (begins != 1 || ends != 1)
        return {false, "",
                fmt::format("expected exactly one '{}' line and one '{}' line, found {} and {}", begin_marker,
                            end_marker, begins, ends)};
    if (inside) return {false, "", fmt::format("'{}' is never closed by '{}'", begin_marker, end_marker)};
    s.found = true;
    return s;
}

bool has_row(const std::vector<std::string>& lines, std::string_view prefix) {
    for (const std::string& l : lines)
        if (l.starts_with(prefix)) return true;
    return false;
}

std::string how_to_fix(const std::string& expected, const std::string& written_to) {
    return fmt::format(
        "\nHow to fix: copy the table printed by this test into docs/parameters.md, between the lines\n"
        "{}\nand\n{}\n"
        "(nothing else between them, no blank lines). The expected table is also in {}.\n"
        "---- expected table ----\n{}---- end ----\n",
        begin_marker, end_marker, written_to, expected);
}

TEST(ReadmeTable, MatchesTheRegistry) {
    const std::string expected = format_params_markdown();
    const auto out = test::output_dir() / "params-table.md";
    std::ofstream(out, std::ios::binary) << expected;

    const std::string path = PUDDLE_SOURCE_DIR "/docs/parameters.md";
    std::ifstream in(path, std::ios::binary);
    ASSERT_TRUE(in) << path << ": cannot open; docs/parameters.md must hold the parameter table."
                    << how_to_fix(expected, out.string());
    std::stringstream text;
    text << in.rdbuf();

    const Section section = find_section(text.str());
    ASSERT_TRUE(section.found) << path << ": " << section.problem << how_to_fix(expected, out.string());
    EXPECT_EQ(section.text, expected)
        << path << ": the parameter table is out of date with src/params/params.def."
        << how_to_fix(expected, out.string());
}

// The table itself: one header, one separator, one row per parameter, in declaration order.
TEST(ReadmeTable, MarkdownHasOneRowPerParameter) {
    const std::string table = format_params_markdown();
    std::istringstream in(table);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    ASSERT_EQ(lines.size(), param_decls().size() + 2);
    EXPECT_EQ(lines[0], "| parameter | type | default | range | what it does |");
    EXPECT_EQ(lines[1], "|---|---|---|---|---|");
    for (std::size_t i = 0; i < param_decls().size(); ++i) {
        const ParamDecl& d = param_decls()[i];
        EXPECT_TRUE(lines[i + 2].starts_with(fmt::format("| `{}` | {} | ", d.name, kind_name(d.kind))))
            << lines[i + 2];
        EXPECT_TRUE(lines[i + 2].ends_with(fmt::format(" | {} |", d.help))) << lines[i + 2];
    }
    const ParamDecl& drops = decl(ParamId::rain_drop_count);
    EXPECT_EQ(lines[2], fmt::format("| `rain.drop_count` | int | `{}` | 1 to 128 drops | {} |",
                                    format_value(drops.default_value), drops.help));
    EXPECT_TRUE(has_row(lines, "| `render.method` | enum | `\"intersect\"` | intersect, raymarch | "));
    EXPECT_TRUE(has_row(lines, "| `ground.image` | text | `\"\"` | text | "));
    EXPECT_TRUE(has_row(lines, "| `wave.damping` | float | `"));
}

// Integer bounds are printed in full, as describe_range() does ("0 to 2147483647", not "2.14748e+09").
TEST(ReadmeTable, RangesArePrintedInFull) {
    const std::string table = format_params_markdown();
    EXPECT_TRUE(table.find("| `rain.seed` | int | `1` | 0 to 2147483647 | ") != std::string::npos) << table;
    EXPECT_TRUE(table.find("| `rain.drop_count` | int | `") != std::string::npos) << table;
    EXPECT_TRUE(table.find(" | 1 to 128 drops | ") != std::string::npos) << table;
}

}  // namespace
}  // namespace puddle::params
