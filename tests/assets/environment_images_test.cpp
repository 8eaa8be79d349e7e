// environment.image: one image is a panorama or a cross by its proportions, HDR files stay linear
// floats, and each wrong input is named with its path and what was expected. Also the real files of
// ../shared/assets (skipped with a message when that folder is absent).
#include "assets/environment_images.hpp"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "assets/image_io.hpp"
#include "support/image_bomb.hpp"
#include "support/test_support.hpp"

namespace puddle::assets {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

// Float files (.hdr, .exr) through OIIO, as a panorama tool would write them.
void write_float(const std::string& path, const Image& img) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << OIIO::geterror();
    // RGB only: Radiance .hdr has no alpha. The image's RGBA rows are read with a 16-byte pixel stride.
    const OIIO::ImageSpec spec(img.width, img.height, 3, OIIO::TypeDesc::FLOAT);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, img.data.data(), 4 * sizeof(float)))
        << out->geterror();
    ASSERT_TRUE(out->close());
}

Image flat_float(int w, int h, float v) {
    Image img = Image::make(w, h, PixelFormat::RGBA32F);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixelf(x, y);
            p[0] = p[1] = p[2] = v;
            p[3] = 1.0f;
        }
    return img;
}

TEST(EnvironmentImages, EmptyMeansTheProceduralSky) {
    auto env = load_environment_images("");
    ASSERT_TRUE(env.ok()) << env.error().message;
    ASSERT_TRUE(env->faces.has_value());
    EXPECT_TRUE(env->hdr()) << "the night city's windows and moon are brighter than white";
    EXPECT_EQ(env->source, "procedural night sky");
    EXPECT_EQ(env->faces->faces[0].width, procedural_sky_face_size);
    // environment.face_size, when set, is the procedural sky's face size too.
    auto small = load_environment_images("", 48);
    ASSERT_TRUE(small.ok());
    EXPECT_EQ(small->faces->faces[5].width, 48);
    EXPECT_EQ(small->faces->faces[5].height, 48);
}

TEST(EnvironmentImages, TwoToOneImageIsAPanoramaAndHdrStaysLinear) {
    TempDir dir;
    const std::string path = (dir / "sky.exr").string();
    write_float(path, flat_float(64, 32, 11.5f));
    auto env = load_environment_images(path);
    ASSERT_TRUE(env.ok()) << env.error().message;
    EXPECT_FALSE(env->faces.has_value());
    EXPECT_TRUE(env->hdr());
    EXPECT_EQ(env->panorama.width, 64);
    EXPECT_FLOAT_EQ(env->panorama.pixelf(10, 10)[0], 11.5f) << "radiance beyond 1 is kept";
    EXPECT_EQ(env->source, path);
}

TEST(EnvironmentImages, EightBitPanoramaStaysSrgb) {
    TempDir dir;
    const std::string path = (dir / "sky.png").string();
    Image img = Image::make(32, 16);
    img.pixel8(3, 3)[0] = 128;
    ASSERT_TRUE(write_png(path, img).ok());
    auto env = load_environment_images(path);
    ASSERT_TRUE(env.ok()) << env.error().message;
    EXPECT_FALSE(env->hdr());
    EXPECT_EQ(env->panorama.pixel8(3, 3)[0], 128);
}

TEST(EnvironmentImages, CrossImageGivesFaces) {
    TempDir dir;
    const std::string path = (dir / "cross.hdr").string();
    write_float(path, flat_float(32, 24, 2.0f));
    auto env = load_environment_images(path);
    ASSERT_TRUE(env.ok()) << env.error().message;
    ASSERT_TRUE(env->faces.has_value());
    EXPECT_TRUE(env->hdr());
    EXPECT_EQ(env->faces->faces[5].width, 8);
    EXPECT_NEAR(env->faces->faces[5].pixelf(1, 1)[1], 2.0f, 0.02f);  // .hdr keeps 8 bits of mantissa
}

TEST(EnvironmentImages, PanoramaThatIsNotTwoToOneNamesPathAndShape) {
    TempDir dir;
    const std::string path = (dir / "wide.png").string();
    ASSERT_TRUE(write_png(path, Image::make(300, 200)).ok());
    auto env = load_environment_images(path);
    ASSERT_FALSE(env.ok());
    EXPECT_EQ(env.error().code, ExitCode::Asset);
    EXPECT_EQ(
        env.error().message,
        "environment.image: " + path +
            " is 300x200: expected an equirectangular panorama twice as wide as high (2:1, e.g. 2048x1024), "
            "or a cube cross (4:3 or 3:4)");
}

// Issue 15: the shape is the header's to decide. This PNG claims 16000x16000 (976 MiB of pixels) over a
// few bytes; decoding it first gave the decoder's error after allocating gigabytes, not this one.
TEST(EnvironmentImages, ASkyOfTheWrongShapeIsRefusedFromItsHeaderWithoutDecoding) {
    TempDir dir;
    const std::string path = dir.write("bomb.png", test::png_claiming(16000, 16000));
    const std::size_t peak_before = test::peak_rss_bytes();
    auto env = load_environment_images(path);
    ASSERT_FALSE(env.ok());
    EXPECT_EQ(env.error().message, "environment.image: " + path +
                                       " is 16000x16000: expected an equirectangular panorama twice as wide "
                                       "as high (2:1, e.g. 2048x1024), "
                                       "or a cube cross (4:3 or 3:4)");
    EXPECT_LT(test::peak_rss_bytes() - peak_before, std::size_t{64} << 20) << "no pixel buffer was allocated";
}

TEST(EnvironmentImages, CorruptFileNamesThePath) {
    TempDir dir;
    const std::string path =
        dir.write("broken.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 512 +X 1024\n\x02\x02");
    auto env = load_environment_images(path);
    ASSERT_FALSE(env.ok());
    EXPECT_EQ(env.error().code, ExitCode::Asset);
    EXPECT_EQ(env.error().message.rfind("image: " + path + ": cannot ", 0), 0u) << env.error().message;
}

TEST(EnvironmentImages, SixPathsWithOneHdrFaceMakeAnHdrCube) {
    TempDir dir;
    std::string spec;
    for (std::size_t i = 0; i < 6; ++i) {
        const std::string p = (dir / (std::string(cube_face_names[i]) + (i == 2 ? ".exr" : ".png"))).string();
        if (i == 2) {
            write_float(p, flat_float(4, 4, 5.0f));
        } else {
            Image grey = Image::make(4, 4);
            std::fill(grey.data.begin(), grey.data.end(), std::uint8_t{128});
            ASSERT_TRUE(write_png(p, grey).ok());
        }
        spec += (spec.empty() ? "" : "|") + p;
    }
    auto env = load_environment_images(spec);
    ASSERT_TRUE(env.ok()) << env.error().message;
    ASSERT_TRUE(env->faces.has_value());
    EXPECT_TRUE(env->hdr());
    EXPECT_FLOAT_EQ(env->faces->faces[2].pixelf(0, 0)[0], 5.0f);
    EXPECT_NEAR(env->faces->faces[0].pixelf(0, 0)[0], 0.2158f, 1e-3f) << "sRGB 128 decoded to linear";
}

TEST(EnvironmentImages, FiveOrSevenPathsAreAnError) {
    auto env = load_environment_images("a.png|b.png|c.png|d.png|e.png");
    ASSERT_FALSE(env.ok());
    EXPECT_EQ(env.error().message,
              "environment.image: expected a folder, one image or six paths (px, nx, py, ny, pz, nz), got "
              "'a.png|b.png|c.png|d.png|e.png'");
}

// ../shared/assets: the Poly Haven panorama, the cube folder and the 16-bit PNGs.
TEST(EnvironmentImagesShared, PolyHavenHdrLoadsAsALinearPanorama) {
    const std::string assets = test::shared_assets_dir();
    if (assets.empty()) GTEST_SKIP() << "../shared/assets not found: the real-file tests need it";
    auto env = load_environment_images(assets + "/env.hdr");
    ASSERT_TRUE(env.ok()) << env.error().message;
    EXPECT_TRUE(env->hdr());
    EXPECT_EQ(env->panorama.width, 1024);
    EXPECT_EQ(env->panorama.height, 512);
    // Values the assets README lists, decoded by hand from the file.
    EXPECT_NEAR(env->panorama.pixelf(0, 0)[0], 1.8125f, 1e-4f);
    EXPECT_NEAR(env->panorama.pixelf(0, 0)[2], 2.28125f, 1e-4f);
    EXPECT_NEAR(env->panorama.pixelf(1023, 511)[0], 0.173828f, 1e-4f);
}

TEST(EnvironmentImagesShared, CubemapFolderAndSixteenBitPngsLoad) {
    const std::string assets = test::shared_assets_dir();
    if (assets.empty()) GTEST_SKIP() << "../shared/assets not found: the real-file tests need it";
    auto cube = load_environment_images(assets + "/cubemap");
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    ASSERT_TRUE(cube->faces.has_value());
    EXPECT_FALSE(cube->hdr());
    EXPECT_EQ(cube->faces->faces[0].width, 512);

    // 16-bit integer PNGs are sRGB colour, rounded to 8 bits: 65535 -> 255, 33825 -> 132, 7680 -> 30.
    auto rgb16 = read_color_image(assets + "/extra/rgb16.png");
    ASSERT_TRUE(rgb16.ok()) << rgb16.error().message;
    ASSERT_EQ(rgb16->format, PixelFormat::RGBA8);
    EXPECT_EQ(rgb16->pixel8(0, 15)[0], 255);
    EXPECT_EQ(rgb16->pixel8(0, 15)[1], 132);
    EXPECT_EQ(rgb16->pixel8(31, 31)[2], 255);
    auto gray16 = read_color_image(assets + "/extra/gray16.png");
    ASSERT_TRUE(gray16.ok()) << gray16.error().message;
    EXPECT_EQ(gray16->pixel8(0, 15)[0], 30);
    EXPECT_EQ(gray16->pixel8(0, 15)[2], 30);
}

}  // namespace
}  // namespace puddle::assets
