// PNG files read through the image module's own libpng reader (assets/png_reader.hpp), reached the way
// Puddle reaches it: read_image() and the dlopen()ed module. The files are written here with libpng's
// full API, so every colour type, bit depth, palette, tRNS and interlacing can be made exactly.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"

namespace puddle::assets {
namespace {

struct PngSpec {
    int width = 3, height = 2, bit_depth = 8, color_type = PNG_COLOR_TYPE_RGB;
    bool interlaced = false;
    std::vector<png_color> palette;
    std::vector<png_byte> trns_alpha;  // palette alpha
    bool trns_colour = false;          // tRNS for grey/RGB: the colour in trns_value is transparent
    png_color_16 trns_value{};
};

// Writes a PNG whose rows are `rows` (bytes as the PNG stores them, 16-bit samples big-endian).
void write_png_file(const std::string& path, const PngSpec& s,
                    const std::vector<std::vector<png_byte>>& rows) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, static_cast<png_uint_32>(s.width), static_cast<png_uint_32>(s.height),
                 s.bit_depth, s.color_type, s.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!s.palette.empty()) png_set_PLTE(png, info, s.palette.data(), static_cast<int>(s.palette.size()));
    if (!s.trns_alpha.empty())
        png_set_tRNS(png, info, s.trns_alpha.data(), static_cast<int>(s.trns_alpha.size()), nullptr);
    if (s.trns_colour) png_set_tRNS(png, info, nullptr, 0, &s.trns_value);
    png_write_info(png, info);
    std::vector<png_bytep> pointers;
    for (const auto& r : rows) pointers.push_back(const_cast<png_bytep>(r.data()));
    png_write_image(png, pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

std::vector<int> rgba(const Image& img, int x, int y) {
    const std::uint8_t* p = img.pixel8(x, y);
    return {p[0], p[1], p[2], p[3]};
}

class PngReaderTest : public ::testing::Test {
protected:
    test::TempDir dir;
    std::string path(const std::string& name) const { return (dir / name).string(); }
};

TEST_F(PngReaderTest, PaletteWithTransparencyBecomesStraightRgba) {
    PngSpec s{.width = 3, .height = 1, .bit_depth = 8, .color_type = PNG_COLOR_TYPE_PALETTE};
    s.palette = {{200, 10, 20}, {0, 255, 0}, {1, 2, 3}};
    s.trns_alpha = {0, 128};  // entry 2 has no alpha: opaque
    write_png_file(path("p.png"), s, {{0, 1, 2}});
    auto img = read_image(path("p.png"));
    ASSERT_TRUE(img.ok()) << img.error().message;
    EXPECT_EQ(rgba(*img, 0, 0), (std::vector<int>{200, 10, 20, 0})) << "colour kept under zero alpha";
    EXPECT_EQ(rgba(*img, 1, 0), (std::vector<int>{0, 255, 0, 128}));
    EXPECT_EQ(rgba(*img, 2, 0), (std::vector<int>{1, 2, 3, 255}));
}

TEST_F(PngReaderTest, LowBitGreyIsScaledToEightBits) {
    PngSpec s{.width = 4, .height = 1, .bit_depth = 2, .color_type = PNG_COLOR_TYPE_GRAY};
    write_png_file(path("g2.png"), s, {{0b00011011}});  // samples 0, 1, 2, 3
    auto img = read_image(path("g2.png"));
    ASSERT_TRUE(img.ok()) << img.error().message;
    EXPECT_EQ(rgba(*img, 0, 0), (std::vector<int>{0, 0, 0, 255}));
    EXPECT_EQ(rgba(*img, 1, 0), (std::vector<int>{85, 85, 85, 255}));
    EXPECT_EQ(rgba(*img, 3, 0), (std::vector<int>{255, 255, 255, 255}));
}

TEST_F(PngReaderTest, GreyAlphaAndAGreyTransparentColour) {
    write_png_file(path("ga.png"),
                   {.width = 2, .height = 1, .bit_depth = 8, .color_type = PNG_COLOR_TYPE_GRAY_ALPHA},
                   {{10, 20, 30, 40}});
    auto ga = read_image(path("ga.png"));
    ASSERT_TRUE(ga.ok()) << ga.error().message;
    EXPECT_EQ(rgba(*ga, 1, 0), (std::vector<int>{30, 30, 30, 40}));

    PngSpec key{.width = 2, .height = 1, .bit_depth = 8, .color_type = PNG_COLOR_TYPE_GRAY};
    key.trns_colour = true;
    key.trns_value.gray = 7;
    write_png_file(path("key.png"), key, {{7, 8}});
    auto keyed = read_image(path("key.png"));
    ASSERT_TRUE(keyed.ok()) << keyed.error().message;
    EXPECT_EQ(rgba(*keyed, 0, 0), (std::vector<int>{7, 7, 7, 0}));
    EXPECT_EQ(rgba(*keyed, 1, 0), (std::vector<int>{8, 8, 8, 255}));
}

// Sixteen-bit samples: rounded to 8 bits as OpenImageIO did (v / 257, nearest), or scaled to [0, 1].
TEST_F(PngReaderTest, SixteenBitRgbaRoundsOrScales) {
    const PngSpec s{.width = 1, .height = 1, .bit_depth = 16, .color_type = PNG_COLOR_TYPE_RGB_ALPHA};
    // 33825 (0x8421) -> 131.6 -> 132; 128 (0x0080) -> 0.498 -> 0; 129 (0x0081) -> 0.502 -> 1; 65535.
    write_png_file(path("16.png"), s, {{0x84, 0x21, 0x00, 0x80, 0x00, 0x81, 0xff, 0xff}});
    auto eight = read_image(path("16.png"));
    ASSERT_TRUE(eight.ok()) << eight.error().message;
    EXPECT_EQ(rgba(*eight, 0, 0), (std::vector<int>{132, 0, 1, 255}));
    auto floats = read_image(path("16.png"), PixelFormat::RGBA32F);
    ASSERT_TRUE(floats.ok()) << floats.error().message;
    EXPECT_FLOAT_EQ(floats->pixelf(0, 0)[0], 33825.0f / 65535.0f);
    EXPECT_FLOAT_EQ(floats->pixelf(0, 0)[3], 1.0f);
}

// Adam7 interlacing stores the pixels in seven passes; the image must come out in place.
TEST_F(PngReaderTest, InterlacedEqualsProgressive) {
    std::vector<std::vector<png_byte>> rows;
    for (int y = 0; y < 9; ++y) {
        rows.emplace_back();
        for (int x = 0; x < 11; ++x)
            for (int c = 0; c < 3; ++c) rows.back().push_back(static_cast<png_byte>(x * 20 + y * 3 + c));
    }
    PngSpec s{.width = 11, .height = 9, .bit_depth = 8, .color_type = PNG_COLOR_TYPE_RGB};
    write_png_file(path("flat.png"), s, rows);
    s.interlaced = true;
    write_png_file(path("adam7.png"), s, rows);
    auto flat = read_image(path("flat.png"));
    auto adam7 = read_image(path("adam7.png"));
    ASSERT_TRUE(flat.ok() && adam7.ok());
    EXPECT_EQ(adam7->data, flat->data);
    EXPECT_EQ(rgba(*adam7, 10, 8), (std::vector<int>{224, 225, 226, 255}));
}

// A truncated or corrupt file is one line naming what is wrong, from libpng, and nothing on stderr
// (OpenImageIO's PNG reader let libpng print "libpng error: ..." beside Puddle's own line).
TEST_F(PngReaderTest, ACorruptFileIsOneLineAndNothingOnStderr) {
    std::vector<std::vector<png_byte>> rows(64, std::vector<png_byte>(64 * 3));
    for (std::size_t y = 0; y < rows.size(); ++y)
        for (std::size_t i = 0; i < rows[y].size(); ++i) rows[y][i] = static_cast<png_byte>(y * 31 + i * 7);
    write_png_file(path("whole.png"), {.width = 64, .height = 64}, rows);
    const std::string whole = test::read_file(path("whole.png"));
    std::ofstream(path("cut.png"), std::ios::binary) << whole.substr(0, whole.size() / 2);
    std::string crc = whole;
    crc[crc.size() - 16] = static_cast<char>(crc[crc.size() - 16] ^ 0x55);  // the last IDAT chunk's CRC
    std::ofstream(path("crc.png"), std::ios::binary) << crc;

    ::testing::internal::CaptureStderr();
    auto cut = read_image(path("cut.png"));
    auto bad_crc = read_image(path("crc.png"));
    const std::string stderr_text = ::testing::internal::GetCapturedStderr();
    ASSERT_FALSE(cut.ok());
    EXPECT_EQ(cut.error().code, ExitCode::Asset);
    EXPECT_EQ(cut.error().message,
              "image: " + path("cut.png") + ": cannot decode: the file ends early (truncated?)");
    ASSERT_FALSE(bad_crc.ok());
    EXPECT_EQ(bad_crc.error().message, "image: " + path("crc.png") + ": cannot decode: IDAT: CRC error");
    EXPECT_EQ(stderr_text, "");
}

}  // namespace
}  // namespace puddle::assets
