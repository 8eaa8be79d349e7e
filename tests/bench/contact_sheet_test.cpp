// puddle-contact-sheet (src/bench/contact_sheet.cpp) run as a user runs it: one PNG with a tile per look,
// the legend in the order of the tiles, and tiles that are the different looks they name.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

TEST(ContactSheet, OneTileALookInTheLegendsOrder) {
    const std::string sheet = (output_dir() / "contact-sheet-test.png").string();
    const CommandResult r = run_command(program_command(PUDDLE_BUILD_DIR "/puddle-contact-sheet") +
                                        " --seconds 0.2 --tile 64x36 --columns 3 " + sheet + " 2>&1");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("row 1, column 1: default\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("row 1, column 2: downpour\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("contact sheet: "), std::string::npos) << r.output;
    // Where the legend puts the ocean (after the presets, whose number depends on the folders present).
    const auto ocean = r.output.find(": scene.kind = ocean\n");
    ASSERT_NE(ocean, std::string::npos) << r.output;
    int row = 0, column = 0;
    ASSERT_EQ(
        std::sscanf(r.output.c_str() + r.output.rfind("row ", ocean), "row %d, column %d", &row, &column), 2);
    int looks = 0;
    for (std::size_t at = r.output.find("row "); at != std::string::npos;
         at = r.output.find("\nrow ", at + 1))
        ++looks;
    EXPECT_GE(looks, 10) << "the default, six shipped presets, the ocean, the street and the window";
    EXPECT_NE(r.output.find(": scene.kind = window\n"), std::string::npos) << "every scene params.def lists";
    auto image = assets::read_image(sheet);
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_EQ(image->width, 3 * 64);
    EXPECT_EQ(image->height, (looks + 2) / 3 * 36);
    // The ocean's tile is another picture than the default's (row 1, column 1).
    const int x = (column - 1) * 64, y = (row - 1) * 36;
    EXPECT_GT(std::abs(mean_luma(*image, x, y, x + 64, y + 36) - mean_luma(*image, 0, 0, 64, 36)), 5.0);
    EXPECT_GT(luma_stddev(*image, 0, 0, 64, 36), 2.0) << "the default tile is a picture, not black";

    const CommandResult bad = run_command(program_command(PUDDLE_BUILD_DIR "/puddle-contact-sheet") +
                                          " /nonexistent-folder/sheet.png 2>&1");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.output.find("the folder /nonexistent-folder does not exist"), std::string::npos)
        << bad.output;
}

}  // namespace
}  // namespace puddle::test
