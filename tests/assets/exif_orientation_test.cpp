// EXIF orientation (assets/orientation.hpp): a JPEG stored turned, with the Orientation tag that makes
// image viewers show it upright, reads upright and in the size viewers show (tags 5 to 8 swap width and
// height, before the size checks). All eight tags, written here through OpenImageIO; then the shared case
// images written by ImageMagick and exiftool (skipped without ../shared).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"

namespace puddle::assets {
namespace {

using Rgb = std::array<int, 3>;
constexpr Rgb red{220, 30, 30}, green{30, 200, 40}, blue{30, 50, 210}, white{240, 240, 240};

// The upright picture: 64x32 (a 2:1 sky), quadrants red (top left), green, blue, white (bottom right).
struct Quadrants {
    Rgb tl, tr, bl, br;
};
constexpr Quadrants upright{red, green, blue, white};

// How a camera stores the upright picture for each tag (EXIF 2.32: which visual side the stored 0th row
// and 0th column are): the stored quadrants, and whether it is stored portrait (32x64).
struct Stored {
    int tag;
    Quadrants q;
    bool portrait;
};
constexpr Stored stored_forms[] = {
    {1, {red, green, blue, white}, false}, {2, {green, red, white, blue}, false},
    {3, {white, blue, green, red}, false}, {4, {blue, white, red, green}, false},
    {5, {red, blue, green, white}, true},  {6, {green, white, red, blue}, true},
    {7, {white, green, blue, red}, true},  {8, {blue, red, white, green}, true},
};

// A JPEG of quadrants, quality 100; the quadrants fall on whole 16x16 blocks so that chroma does not bleed.
void write_jpeg(const std::string& path, const Stored& s) {
    const int w = s.portrait ? 32 : 64, h = s.portrait ? 64 : 32;
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w * h * 3));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const bool right = x >= w / 2, bottom = y >= h / 2;
            const Rgb& c = bottom ? (right ? s.q.br : s.q.bl) : (right ? s.q.tr : s.q.tl);
            for (int k = 0; k < 3; ++k)
                rgb[static_cast<std::size_t>((y * w + x) * 3 + k)] =
                    static_cast<std::uint8_t>(c[static_cast<std::size_t>(k)]);
        }
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("Orientation", s.tag);
    spec.attribute("CompressionQuality", 100);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, rgb.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

// A pixel as 0..255 values, from either format.
Rgb at(const Image& img, int x, int y) {
    if (img.format == PixelFormat::RGBA8) {
        const std::uint8_t* p = img.pixel8(x, y);
        return {p[0], p[1], p[2]};
    }
    const float* p = img.pixelf(x, y);
    return {int(p[0] * 255 + 0.5f), int(p[1] * 255 + 0.5f), int(p[2] * 255 + 0.5f)};
}

bool near(const Rgb& a, const Rgb& b) {
    for (std::size_t k = 0; k < 3; ++k)
        if (std::abs(a[k] - b[k]) > 24) return false;
    return true;
}

std::string text(const Rgb& c) {
    return std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]);
}

TEST(ExifOrientation, AllEightTagsReadUprightInTheSizeViewersShow) {
    test::TempDir dir;
    for (const Stored& s : stored_forms) {
        const std::string path = (dir / ("o" + std::to_string(s.tag) + ".jpg")).string();
        write_jpeg(path, s);
        auto info = probe_image(path);
        ASSERT_TRUE(info) << info.error().message;
        EXPECT_EQ(info->width, 64) << "tag " << s.tag << ": the header's size is the size shown";
        EXPECT_EQ(info->height, 32) << "tag " << s.tag;
        for (const PixelFormat format : {PixelFormat::RGBA8, PixelFormat::RGBA32F}) {
            auto image = read_image(path, format);
            ASSERT_TRUE(image) << image.error().message;
            ASSERT_EQ(image->width, 64) << "tag " << s.tag;
            ASSERT_EQ(image->height, 32) << "tag " << s.tag;
            const struct {
                int x, y;
                const Rgb& want;
                const char* where;
            } probes[] = {{16, 8, upright.tl, "top left"},
                          {48, 8, upright.tr, "top right"},
                          {16, 24, upright.bl, "bottom left"},
                          {48, 24, upright.br, "bottom right"}};
            for (const auto& p : probes)
                EXPECT_TRUE(near(at(*image, p.x, p.y), p.want))
                    << "tag " << s.tag << (format == PixelFormat::RGBA8 ? " (8 bits)" : " (float)") << ", "
                    << p.where << ": " << text(at(*image, p.x, p.y));
        }
    }
}

// The field report's files (ImageMagick turned them, exiftool tagged them): each reads as upright.jpg does.
TEST(ExifOrientation, TheSharedCaseImagesReadAsTheUprightOne) {
    const std::filesystem::path cases = PUDDLE_SHARED_DIR "/cases/turn3/exif_orientation_still_ignored";
    if (!std::filesystem::exists(cases / "upright.jpg"))
        GTEST_SKIP() << "no " << cases.string() << " (the shared folder is not checked out)";
    auto upright_image = read_image((cases / "upright.jpg").string());
    ASSERT_TRUE(upright_image) << upright_image.error().message;
    for (const char* name : {"stored_o3.jpg", "stored_o6.jpg", "stored_o8.jpg"}) {
        auto image = read_image((cases / name).string());
        ASSERT_TRUE(image) << name << ": " << image.error().message;
        ASSERT_EQ(image->width, upright_image->width) << name;
        ASSERT_EQ(image->height, upright_image->height) << name;
        const test::ImageDiff d = test::compare_images(*image, *upright_image, 40);
        EXPECT_LT(d.mean_abs_diff, 4.0) << name << ": mean difference " << d.mean_abs_diff << " of 255";
    }
}

}  // namespace
}  // namespace puddle::assets
