#include "assets/image_io.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "assets/image_limits.hpp"
#include "support/image_bomb.hpp"

namespace puddle::assets {
namespace {

namespace fs = std::filesystem;

const std::string kExtra = PUDDLE_SHARED_DIR "/assets/extra";
const std::string kEnvHdr = PUDDLE_SHARED_DIR "/assets/env.hdr";

// A fresh folder per test, removed afterwards.
class ImageIoTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        // The pid keeps concurrent runs (two build trees, ctest -j) out of each other's way.
        dir_ = fs::temp_directory_path() /
               (std::string("puddle-image-io-") + info->name() + "-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void write_bytes(const std::string& name, const std::string& bytes) const {
        std::ofstream(path(name), std::ios::binary) << bytes;
    }

    fs::path dir_;
};

// Every channel of every pixel differs, alpha included, so swaps and premultiplication both show.
Image pattern(int w, int h) {
    Image img = Image::make(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = img.pixel8(x, y);
            p[0] = static_cast<std::uint8_t>(x * 7 + y);
            p[1] = static_cast<std::uint8_t>(y * 13 + 5);
            p[2] = static_cast<std::uint8_t>((x ^ y) * 3);
            p[3] = static_cast<std::uint8_t>(255 - x - 2 * y);
        }
    }
    return img;
}

void expect_rgba8(const Image& img, int x, int y, int r, int g, int b, int a = 255) {
    const std::uint8_t* p = img.pixel8(x, y);
    EXPECT_EQ(p[0], r) << "red at (" << x << "," << y << ")";
    EXPECT_EQ(p[1], g) << "green at (" << x << "," << y << ")";
    EXPECT_EQ(p[2], b) << "blue at (" << x << "," << y << ")";
    EXPECT_EQ(p[3], a) << "alpha at (" << x << "," << y << ")";
}

TEST_F(ImageIoTest, WritePngThenReadGivesTheSamePixels) {
    const Image original = pattern(37, 21);  // odd sizes catch stride mistakes
    ASSERT_TRUE(write_png(path("round.png"), original).ok());
    EXPECT_FALSE(fs::exists(path("round.png.tmp"))) << "the temporary file is renamed into place";

    auto read = read_image(path("round.png"));
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->width, 37);
    EXPECT_EQ(read->height, 21);
    EXPECT_EQ(read->format, PixelFormat::RGBA8);
    EXPECT_EQ(read->data, original.data);
}

TEST_F(ImageIoTest, ReadsAsFloatScaledToOne) {
    ASSERT_TRUE(write_png(path("f.png"), pattern(4, 3)).ok());
    auto read = read_image(path("f.png"), PixelFormat::RGBA32F);
    ASSERT_TRUE(read.ok()) << read.error().message;
    ASSERT_EQ(read->format, PixelFormat::RGBA32F);
    ASSERT_EQ(read->data.size(), 4u * 3u * 16u);
    const float* p = read->pixelf(3, 2);  // pattern: (23, 31, 3, 248)
    EXPECT_NEAR(p[0], 23.0f / 255.0f, 1e-6f);
    EXPECT_NEAR(p[1], 31.0f / 255.0f, 1e-6f);
    EXPECT_NEAR(p[2], 3.0f / 255.0f, 1e-6f);
    EXPECT_NEAR(p[3], 248.0f / 255.0f, 1e-6f);
}

TEST_F(ImageIoTest, SixteenBitRgbPngRoundsTo8Bits) {
    if (!fs::exists(kExtra)) GTEST_SKIP() << "shared test images not found at " << kExtra;
    auto img = read_image(kExtra + "/rgb16.png");
    ASSERT_TRUE(img.ok()) << img.error().message;
    ASSERT_EQ(img->width, 32);
    ASSERT_EQ(img->height, 32);
    expect_rgba8(*img, 0, 0, 255, 255, 0);
    expect_rgba8(*img, 31, 31, 0, 0, 255);
    expect_rgba8(*img, 0, 15, 255, 132, 0);  // 33825 / 65535 * 255 = 131.6
}

TEST_F(ImageIoTest, SixteenBitGreyPngBecomesOpaqueGreyRgb) {
    if (!fs::exists(kExtra)) GTEST_SKIP() << "shared test images not found at " << kExtra;
    auto img = read_image(kExtra + "/gray16.png");
    ASSERT_TRUE(img.ok()) << img.error().message;
    ASSERT_EQ(img->width, 32);
    expect_rgba8(*img, 0, 0, 0, 0, 0);
    expect_rgba8(*img, 31, 31, 1, 1, 1);    // 255 / 65535 * 255 = 0.99
    expect_rgba8(*img, 0, 15, 30, 30, 30);  // 7680 / 65535 * 255 = 29.9
}

TEST_F(ImageIoTest, HdrKeepsLinearValuesAsFloat) {
    if (!fs::exists(kEnvHdr)) GTEST_SKIP() << "shared test image not found at " << kEnvHdr;
    auto img = read_image(kEnvHdr, PixelFormat::RGBA32F);
    ASSERT_TRUE(img.ok()) << img.error().message;
    ASSERT_EQ(img->width, 1024);
    ASSERT_EQ(img->height, 512);
    const float* p = img->pixelf(0, 0);
    EXPECT_NEAR(p[0], 1.8125f, 1e-3f);
    EXPECT_NEAR(p[1], 1.90625f, 1e-3f);
    EXPECT_NEAR(p[2], 2.28125f, 1e-3f);
    EXPECT_FLOAT_EQ(p[3], 1.0f);
    const float* last = img->pixelf(1023, 511);  // rows top first: the last row is the bottom one
    EXPECT_NEAR(last[0], 0.173828f, 1e-3f);
    EXPECT_NEAR(last[1], 0.092773f, 1e-3f);
}

// A Radiance header claiming a size, with no pixels after it: what a few bytes of a wrong file can say.
std::string hdr_header(int width, int height) {
    return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " +
           std::to_string(width) + "\n";
}

TEST_F(ImageIoTest, WiderThanTheSideLimitIsRefusedFromTheHeader) {
    write_bytes("wide.hdr", hdr_header(max_image_side + 1, 2));
    auto img = read_color_image(path("wide.hdr"));
    ASSERT_FALSE(img.ok());
    EXPECT_EQ(img.error().code, ExitCode::Asset);
    EXPECT_EQ(img.error().message, "image: " + path("wide.hdr") + ": " + std::to_string(max_image_side + 1) +
                                       "x2 is too large: at most " + std::to_string(max_image_side) +
                                       " pixels a side");
}

TEST_F(ImageIoTest, MoreDecodedBytesThanTheLimitAreRefusedBeforeDecoding) {
    // 12000x12000 float pixels would be 2197 MiB: refused from the header, nothing allocated.
    write_bytes("huge.hdr", hdr_header(12000, 12000));
    auto img = read_color_image(path("huge.hdr"));
    ASSERT_FALSE(img.ok());
    EXPECT_EQ(img.error().message,
              "image: " + path("huge.hdr") +
                  ": 12000x12000 RGBA32F needs 2197 MiB decoded, more than the 1024 MiB limit");
}

TEST_F(ImageIoTest, ProbeGivesTheHeadersSizeWithoutDecoding) {
    write_bytes("bomb.png", test::png_claiming(16000, 16000));
    const std::size_t peak_before = test::peak_rss_bytes();
    auto info = probe_image(path("bomb.png"));
    ASSERT_TRUE(info.ok()) << info.error().message;
    EXPECT_EQ(info->width, 16000);
    EXPECT_EQ(info->height, 16000);
    EXPECT_EQ(info->format, PixelFormat::RGBA8);
    EXPECT_EQ(info->decoded_bytes(), std::size_t{16000} * 16000 * 4);
    EXPECT_LT(test::peak_rss_bytes() - peak_before, std::size_t{64} << 20) << "no pixel buffer was allocated";
    // The pixels themselves are broken: only a decode finds that out.
    EXPECT_FALSE(read_image(path("bomb.png"), PixelFormat::RGBA8).ok());
}

TEST_F(ImageIoTest, ProbeOfAColorImageSaysFloatForHdrAndAppliesTheLimits) {
    write_bytes("wide.hdr", hdr_header(max_image_side + 1, 2));
    auto wide = probe_color_image(path("wide.hdr"));
    ASSERT_FALSE(wide.ok());
    EXPECT_EQ(wide.error().message, "image: " + path("wide.hdr") + ": " + std::to_string(max_image_side + 1) +
                                        "x2 is too large: at most " + std::to_string(max_image_side) +
                                        " pixels a side");
    write_bytes("sky.hdr", hdr_header(64, 32));
    auto sky = probe_color_image(path("sky.hdr"));
    ASSERT_TRUE(sky.ok()) << sky.error().message;
    EXPECT_EQ(sky->width, 64);
    EXPECT_EQ(sky->height, 32);
    EXPECT_EQ(sky->format, PixelFormat::RGBA32F);
    EXPECT_EQ(probe_image(path("sky.hdr"))->format, PixelFormat::RGBA8) << "read_image's default converts";
}

// A FIFO in a mock camera folder, or named as the sky, once hung start-up inside the decoder's open().
TEST_F(ImageIoTest, AFifoIsRefusedWithoutWaitingForAWriter) {
    const std::string fifo = path("sky.png");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto img = read_image(fifo);
    ASSERT_FALSE(img.ok());
    EXPECT_EQ(img.error().code, ExitCode::Asset);
    EXPECT_EQ(img.error().message, "image: " + fifo + ": cannot open: is a FIFO, not a file");
}

TEST_F(ImageIoTest, MissingFileNamesThePathAndTheReason) {
    const std::string missing = path("nope/px.jpg");
    auto img = read_image(missing);
    ASSERT_FALSE(img.ok());
    EXPECT_EQ(img.error().code, ExitCode::Asset);
    EXPECT_EQ(img.error().message, "image: " + missing + ": cannot open: No such file or directory");
}

TEST_F(ImageIoTest, CorruptPngIsAnErrorNamingThePath) {
    write_bytes("corrupt.png", std::string("\x89PNG\r\n\x1a\n", 8) + std::string(200, '\x5a'));
    auto img = read_image(path("corrupt.png"));
    ASSERT_FALSE(img.ok());
    EXPECT_EQ(img.error().code, ExitCode::Asset);
    EXPECT_EQ(img.error().message.rfind("image: " + path("corrupt.png") + ": ", 0), 0u)
        << img.error().message;
    EXPECT_EQ(img.error().message.find('\n'), std::string::npos) << "one line";
}

TEST_F(ImageIoTest, TruncatedPngIsAnError) {
    const Image big = pattern(64, 64);
    ASSERT_TRUE(write_png(path("whole.png"), big).ok());
    std::string bytes(fs::file_size(path("whole.png")), '\0');
    std::ifstream(path("whole.png"), std::ios::binary)
        .read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    write_bytes("cut.png", bytes.substr(0, bytes.size() / 2));
    auto img = read_image(path("cut.png"));
    ASSERT_FALSE(img.ok());
    EXPECT_NE(img.error().message.find(path("cut.png")), std::string::npos) << img.error().message;
}

TEST_F(ImageIoTest, TextFileNamedJpgIsAnError) {
    write_bytes("notes.jpg", "these are not the pixels you are looking for\n");
    auto img = read_image(path("notes.jpg"));
    ASSERT_FALSE(img.ok());
    EXPECT_EQ(img.error().code, ExitCode::Asset);
    EXPECT_NE(img.error().message.find(path("notes.jpg")), std::string::npos) << img.error().message;
}

TEST_F(ImageIoTest, FolderIsNotAnImage) {
    auto img = read_image(dir_.string());
    ASSERT_FALSE(img.ok());
    EXPECT_EQ(img.error().message, "image: " + dir_.string() + ": cannot open: is a directory");
}

}  // namespace
}  // namespace puddle::assets
