// The [wall] rule across keys (params/wall_check.hpp): this screen's column and row lie inside the wall.
// Checked on the preset, the config and the command line together when a config is taken (start-up,
// --check, reloads); the message names the line or the --set that placed the screen.
#include "params/wall_check.hpp"

#include <gtest/gtest.h>

#include "params/param_layers.hpp"
#include "support/parsed_config.hpp"

namespace puddle::params {
namespace {

ParamLayers layers(std::vector<ConfigEntry> command_line = {}) {
    return ParamLayers(Presets::load({}), std::move(command_line));
}

TEST(WallCheck, ColumnPastTheWallNamesItsLineAndTheAllowedRange) {
    ParamLayers l = layers();
    auto r = l.set_config(test::parsed_config("[wall]\ncolumns = 2\nrows = 2\ncolumn = 2\n"));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ExitCode::Config);
    EXPECT_EQ(
        r.error().message,
        "config: test.toml:4: wall.column = 2 is out of range: allowed 0 to 1 (0-based; wall.columns = 2)");
}

TEST(WallCheck, RowPastTheWallNamesItsLine) {
    ParamLayers l = layers();
    auto r = l.set_config(test::parsed_config("[wall]\ncolumns = 3\nrow = 1\n"));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message,
              "config: test.toml:3: wall.row = 1 is out of range: allowed 0 to 0 (0-based; wall.rows = 1)");
}

TEST(WallCheck, EveryScreenOfTheWallIsAccepted) {
    for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 2; ++row) {
            ParamLayers l = layers();
            const std::string text = "[wall]\ncolumns = 3\nrows = 2\ncolumn = " + std::to_string(column) +
                                     "\nrow = " + std::to_string(row) + "\n";
            auto r = l.set_config(test::parsed_config(text.c_str()));
            EXPECT_TRUE(r) << r.error().message;
            EXPECT_EQ(l.compose().get<ParamId::wall_column>(), column);
        }
}

// The config says 2 columns and --set puts the screen in the third: the command line is named.
TEST(WallCheck, CommandLineAcrossLayersIsChecked) {
    auto set = parse_assignment("wall.column=2");
    ASSERT_TRUE(set);
    ParamLayers l = layers({*set});
    auto r = l.set_config(test::parsed_config("[wall]\ncolumns = 2\n"));
    ASSERT_FALSE(r);
    EXPECT_EQ(
        r.error().message,
        "--set wall.column=2: wall.column = 2 is out of range: allowed 0 to 1 (0-based; wall.columns = 2, "
        "from config: test.toml:2)");
}

// The config places the screen and --set shrinks the wall: both are named, the person fixes either.
TEST(WallCheck, AWallShrunkOnTheCommandLineNamesTheSetToo) {
    auto set = parse_assignment("wall.columns=1");
    ASSERT_TRUE(set);
    ParamLayers l = layers({*set});
    auto r = l.set_config(test::parsed_config("[wall]\ncolumns = 2\ncolumn = 1\n"));
    ASSERT_FALSE(r);
    EXPECT_EQ(
        r.error().message,
        "config: test.toml:3: wall.column = 1 is out of range: allowed 0 to 0 (0-based; wall.columns = 1, "
        "from --set wall.columns=1)");
}

// A reload that moves the screen off the wall is refused and the last good config stays.
TEST(WallCheck, RefusedReloadKeepsTheLastGoodConfig) {
    ParamLayers l = layers();
    ASSERT_TRUE(l.set_config(test::parsed_config("[wall]\ncolumns = 2\ncolumn = 1\n")));
    EXPECT_FALSE(l.set_config(test::parsed_config("[wall]\ncolumns = 1\ncolumn = 1\n")));
    EXPECT_EQ(l.compose().get<ParamId::wall_columns>(), 2);
    EXPECT_EQ(l.compose().get<ParamId::wall_column>(), 1);
}

// Without a config file start-up checks the composed values alone (app.cpp).
TEST(WallCheck, ComposedValuesWithoutAConfig) {
    Params p;
    ASSERT_TRUE(p.set(ParamId::wall_row, 3, ParamSource::CommandLine));
    auto r = check_wall(p, {});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message,
              "--set wall.row=3: wall.row = 3 is out of range: allowed 0 to 0 (0-based; wall.rows = 1)");
    EXPECT_TRUE(check_wall(Params{}, {}));
}

}  // namespace
}  // namespace puddle::params
