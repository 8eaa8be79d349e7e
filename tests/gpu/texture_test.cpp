// Textures and samplers (gpu/texture.hpp): the mip chain's length and the storage an error message names;
// on a real context, every format uploaded and read back, uploads of row ranges and padded rows, cube
// faces, mip levels rendered into and generated, and what each sampler's filter and wrap modes fetch.
#include "gpu/texture.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "gpu/device.hpp"
#include "gpu/gl_formats.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::gpu {
namespace {

TEST(FullMipCount, IsFloorLog2PlusOneDownToOneTexel) {
    EXPECT_EQ(full_mip_count(1), 1);
    EXPECT_EQ(full_mip_count(2), 2);
    EXPECT_EQ(full_mip_count(3), 2);
    EXPECT_EQ(full_mip_count(256), 9);
    EXPECT_EQ(full_mip_count(255), 8);
    EXPECT_EQ(full_mip_count(4096), 13);
    EXPECT_EQ(full_mip_count(8192 + 1), 14);
    EXPECT_EQ(full_mip_count(0), 1);
    EXPECT_EQ(full_mip_count(-5), 1);
}

TEST(TextureStorage, CountsBytesOfEveryLevelAndFace) {
    const TextureDesc cube{.kind = TextureKind::Cube,
                           .format = TextureFormat::RGBA16F,
                           .width = 4,
                           .height = 4,
                           .mip_levels = 3};
    EXPECT_EQ(storage_bytes(cube), 6u * 8u * (16 + 4 + 1));
    EXPECT_EQ(describe_storage(cube), "cube 6 x 4x4 RGBA16F, 3 levels, 1008 bytes");
    const TextureDesc sky{.kind = TextureKind::Cube,
                          .format = TextureFormat::SRGB8_A8,
                          .width = 4096,
                          .height = 4096,
                          .mip_levels = 13};
    EXPECT_EQ(describe_storage(sky), "cube 6 x 4096x4096 SRGB8_ALPHA8, 13 levels, 512.0 MiB");
    // A non-square chain: each side halves down to 1 on its own.
    EXPECT_EQ(storage_bytes({.format = TextureFormat::R8, .width = 8, .height = 2, .mip_levels = 4}),
              16u + 4u + 2u + 1u);
}

class TextureTest : public test::DeviceFixture {
protected:
    Texture make(const TextureDesc& desc) {
        auto t = device_->create_texture(desc);
        EXPECT_TRUE(t.ok()) << (t.ok() ? "" : t.error().message);
        return t ? std::move(t).value() : Texture();
    }
};

// What read_texture gives for texels stored as `stored` (the format's channels per texel): GL fills the
// channels a format lacks with 0, 0, 1 (GLES 3.0 section 4.3.2).
std::vector<float> as_rgba(const std::vector<float>& stored, int channels) {
    std::vector<float> rgba;
    for (std::size_t i = 0; i < stored.size(); i += std::size_t(channels))
        for (int c = 0; c < 4; ++c)
            rgba.push_back(c < channels ? stored[i + std::size_t(c)] : c == 3 ? 1.0f : 0.0f);
    return rgba;
}

struct FormatCase {
    TextureFormat format;
    std::vector<float> values;  // 2x2 texels as the format stores them (8-bit formats: bytes / 255)
};

// Each format the device offers, uploaded as Texture::upload documents and read back in the same order
// (row 0 = t 0). Values are exact in the format (halves for RGBA16F), so any change is a failure.
TEST_F(TextureTest, EveryOfferedFormatReadsBackWhatWasUploaded) {
    const Capabilities& caps = device_->caps();
    std::vector<FormatCase> cases{
        {TextureFormat::RGBA8, {0, 1, 2, 3, 64, 128, 192, 255, 10, 20, 30, 40, 250, 5, 100, 0}},
        {TextureFormat::SRGB8_A8, {0, 1, 2, 3, 64, 128, 192, 255, 10, 20, 30, 40, 250, 5, 100, 0}},
        {TextureFormat::RG32I, {-70000, 123456, 0, 1, -1, 16777216, -8388607, 42}},
    };
    if (caps.float_render_targets) {
        cases.push_back({TextureFormat::RG32F, {1.5f, -2.25f, 1e-6f, 3.0f, 0.1f, -0.1f, 65504.0f, -1e20f}});
        cases.push_back({TextureFormat::RGBA32F,
                         {0.1f, 0.2f, 0.3f, 0.4f, -5, 6, -7, 8, 1e10f, -1e-10f, 0, 1, 3.14159f, 2.71828f,
                          1.41421f, 0.5f}});
    }
    if (caps.half_float_render_targets)
        cases.push_back(
            {TextureFormat::RGBA16F,
             {0.5f, -2, 1024, 0.125f, 1.5f, -0.25f, 3, 2048, 0, 1, -1, 65504, 0.0009765625f, 7, -8, 0.75f}});
    for (const FormatCase& c : cases) {
        SCOPED_TRACE(format_name(c.format));
        const GlFormat gl = gl_format(c.format);
        Texture t = make({.label = "round trip", .format = c.format, .width = 2, .height = 2});
        std::vector<std::byte> data;
        std::vector<float> expected = c.values;
        for (float& v : expected) {
            if (gl.bytes_per_channel == 1) {
                data.push_back(std::byte(static_cast<unsigned char>(v)));
                v /= 255.0f;
            } else if (c.format == TextureFormat::RG32I) {
                const int i = static_cast<int>(v);
                data.insert(data.end(), reinterpret_cast<const std::byte*>(&i),
                            reinterpret_cast<const std::byte*>(&i) + 4);
            } else {
                data.insert(data.end(), reinterpret_cast<const std::byte*>(&v),
                            reinterpret_cast<const std::byte*>(&v) + 4);
            }
        }
        t.upload(data);
        const std::vector<float> back = device_->read_texture(t);
        const std::vector<float> want = as_rgba(expected, gl.channels);
        ASSERT_EQ(back.size(), want.size());
        for (std::size_t i = 0; i < want.size(); ++i) EXPECT_FLOAT_EQ(back[i], want[i]) << "value " << i;
        EXPECT_EQ(device_->take_errors(), "");
    }
}

std::vector<std::byte> bytes_of(const std::vector<glm::u8vec4>& texels) {
    const auto b = std::as_bytes(std::span(texels));
    return {b.begin(), b.end()};
}

// A 2x2 camera plane (R8: Y, RG8: UV) holding the first 4 * channels of plane_bytes, texel i at byte
// i * channels.
const std::vector<unsigned char> plane_bytes{0, 255, 1, 254, 100, 50, 200, 150};
Texture make_plane(Device& device, TextureFormat format) {
    auto t = device.create_texture({.label = "plane", .format = format, .width = 2, .height = 2});
    EXPECT_TRUE(t.ok()) << t.error().message;
    t->upload(std::as_bytes(std::span(plane_bytes.data(), std::size_t(4 * gl_format(format).channels))));
    return std::move(*t);
}

// R8 and RG8 (a camera's Y and UV planes) drawn into an RGBA8 target, one pixel per texel, as the camera
// shader samples them. Missing channels sample as 0, 0, 1.
TEST_F(TextureTest, OneAndTwoChannelByteFormatsSampleAsUploaded) {
    const Pipeline copy = test::make_copy_pipeline(*device_, Blend::Replace);
    for (const TextureFormat format : {TextureFormat::R8, TextureFormat::RG8}) {
        SCOPED_TRACE(format_name(format));
        const int channels = gl_format(format).channels;
        const std::vector<unsigned char>& bytes = plane_bytes;
        Texture t = make_plane(*device_, format);
        Texture target = test::make_target(*device_, {2, 2}, {1, 0, 1, 0});
        test::draw_texture(*device_, target, copy, t);
        const std::vector<glm::u8vec4> drawn = test::read_texels(*device_, target);
        for (int i = 0; i < 4; ++i) {
            // Texel i is at row i / 2 from the bottom; drawn rows start at the top.
            const glm::u8vec4 got = drawn[std::size_t((1 - i / 2) * 2 + i % 2)];
            const std::size_t at = std::size_t(i * channels);
            EXPECT_EQ(got, glm::u8vec4(bytes[at], channels > 1 ? bytes[at + 1] : 0, 0, 255)) << "texel " << i;
        }
    }
}

// read_texture reads normalised one- and two-channel textures as bytes / 255 (glReadPixels refuses
// GL_FLOAT for them); the channels they lack read as 0, and alpha as 1.
TEST_F(TextureTest, ReadTextureGivesOneAndTwoChannelBytesOverTwoFiftyFive) {
    for (const TextureFormat format : {TextureFormat::R8, TextureFormat::RG8}) {
        SCOPED_TRACE(format_name(format));
        const int channels = gl_format(format).channels;
        const std::vector<unsigned char>& bytes = plane_bytes;
        Texture t = make_plane(*device_, format);
        const std::vector<float> back = device_->read_texture(t);
        EXPECT_EQ(device_->take_errors(), "");
        ASSERT_EQ(back.size(), 16u);
        for (int i = 0; i < 4; ++i) {
            const std::size_t at = std::size_t(i * channels), px = std::size_t(4 * i);
            EXPECT_FLOAT_EQ(back[px], bytes[at] / 255.0f) << "texel " << i;
            EXPECT_FLOAT_EQ(back[px + 1], channels > 1 ? bytes[at + 1] / 255.0f : 0.0f) << "texel " << i;
            EXPECT_FLOAT_EQ(back[px + 3], 1.0f) << "texel " << i;
        }
    }
}

// Texels read back as read_pixels gives them: rows top first, so GL row 0 is the last row here.
TEST_F(TextureTest, UploadRowsReplacesOnlyThoseRows) {
    Texture t = make({.label = "rows", .width = 2, .height = 4});
    const glm::u8vec4 black{0, 0, 0, 255}, white{255, 255, 255, 255}, red{255, 0, 0, 255};
    t.upload(bytes_of(std::vector(8, black)));
    t.upload_rows(bytes_of({red, white, white, red}), 0, 0, 1, 2);  // GL rows 1 and 2
    EXPECT_EQ(test::read_texels(*device_, t),
              (std::vector<glm::u8vec4>{black, black, white, red, red, white, black, black}));
}

// A driver's bytesperline pads rows: 3 texels (12 bytes) 16 bytes apart. Without GL_UNPACK_ROW_LENGTH the
// padding would be read as the next row's first texel.
TEST_F(TextureTest, UploadRowsSkipsThePaddingBetweenRows) {
    Texture t = make({.label = "padded", .width = 3, .height = 2});
    const glm::u8vec4 a{10, 20, 30, 40}, b{50, 60, 70, 80}, c{90, 100, 110, 120}, pad{0xee, 0xee, 0xee, 0xee};
    const glm::u8vec4 d{130, 140, 150, 160}, e{170, 180, 190, 200}, f{210, 220, 230, 240};
    t.upload_rows(bytes_of({a, b, c, pad, d, e, f}), 16);
    EXPECT_EQ(test::read_texels(*device_, t), (std::vector<glm::u8vec4>{d, e, f, a, b, c}));
}

TEST_F(TextureTest, EachCubeFaceHoldsItsOwnUpload) {
    Texture cube = make({.label = "cube", .kind = TextureKind::Cube, .width = 2, .height = 2});
    for (int face = 0; face < 6; ++face) {
        const glm::u8vec4 colour(face * 40, 255 - face * 40, face * 10, 255);
        cube.upload(bytes_of(std::vector(4, colour)), 0, face);
    }
    for (int face = 0; face < 6; ++face) {
        const std::vector<float> back = device_->read_texture(cube, face);
        EXPECT_FLOAT_EQ(back[0], face * 40 / 255.0f) << "face " << face;
        EXPECT_FLOAT_EQ(back[1], (255 - face * 40) / 255.0f) << "face " << face;
        EXPECT_FLOAT_EQ(back[12], face * 40 / 255.0f) << "face " << face << ", last texel";
    }
}

// A pass into level 1, then into level 0 again: fails if Texture::framebuffer kept the first level it
// attached (the second clear would land on level 1).
TEST_F(TextureTest, PassesRenderIntoTheLevelTheyName) {
    Texture t = make({.label = "levels", .width = 4, .height = 4, .mip_levels = 3, .render_target = true});
    auto clear = [&](int level, glm::vec4 colour) {
        const int side = 4 >> level;
        device_->begin_pass({.label = "clear level",
                             .target = {.texture = &t, .size = {side, side}, .level = level},
                             .load = LoadOp::Clear,
                             .clear = colour});
    };
    const glm::u8vec4 red{255, 0, 0, 255}, blue{0, 0, 255, 255}, green{0, 255, 0, 255};
    clear(0, {1, 0, 0, 1});
    clear(1, {0, 0, 1, 1});
    EXPECT_EQ(test::read_texels(*device_, t, 0), std::vector(16, red));
    EXPECT_EQ(test::read_texels(*device_, t, 1), std::vector(4, blue));
    clear(0, {0, 1, 0, 1});
    EXPECT_EQ(test::read_texels(*device_, t, 0), std::vector(16, green));
    EXPECT_EQ(test::read_texels(*device_, t, 1), std::vector(4, blue));
}

// Level 1 is first cleared to blue, so a generate_mipmaps that did nothing leaves blue.
TEST_F(TextureTest, GeneratedMipmapsAverageTheLevelAbove) {
    Texture t = make({.label = "mips", .width = 2, .height = 2, .mip_levels = 2, .render_target = true});
    const std::vector<glm::u8vec4> texels{
        {0, 10, 200, 255}, {255, 30, 100, 255}, {100, 50, 0, 255}, {200, 70, 60, 255}};
    t.upload(bytes_of(texels));
    device_->begin_pass({.label = "level 1",
                         .target = {.texture = &t, .size = {1, 1}, .level = 1},
                         .load = LoadOp::Clear,
                         .clear = {0, 0, 1, 1}});
    t.generate_mipmaps();
    const glm::u8vec4 mean = test::read_texels(*device_, t, 1)[0];
    for (int c = 0; c < 4; ++c) {
        const double want = (texels[0][c] + texels[1][c] + texels[2][c] + texels[3][c]) / 4.0;
        EXPECT_NEAR(mean[c], want, 1.0) << "channel " << c;
    }
}

// A 2x1 texture (black, white) drawn over a 4x1 target. With u_screen_size half the target the lookup
// runs from 0 to 2 across it: texel coordinates 0.5, 1.5, 2.5, 3.5 show each wrap mode (nearest). With
// the target's own size and linear filtering, pixel centres fall at texel coordinates -0.25, 0.25, 0.75,
// 1.25: clamped, the ends are pure and the middle two mix 1/4 and 3/4.
class SamplerTest : public TextureTest {
protected:
    std::vector<int> draw(const SamplerDesc& desc, float screen_width) {
        Texture target = test::make_target(*device_, {4, 1}, {1, 0, 0, 1});
        const Texture black_white = test::make_texels(*device_, {{0, 0, 0, 255}, {255, 255, 255, 255}});
        const Pipeline copy = test::make_copy_pipeline(*device_, Blend::Replace);
        device_->begin_pass({.label = "sample", .target = {&target, {4, 1}}, .load = LoadOp::Load})
            .set_pipeline(copy)
            .set_texture(0, black_white, device_->create_sampler(desc))
            .set("u_quarter_turns", 0)
            .set("u_brightness", 1.0f)
            .set("u_screen_size", glm::vec2(screen_width, 1))
            .draw_fullscreen();
        std::vector<int> grey;
        for (const glm::u8vec4 t : test::read_texels(*device_, target)) grey.push_back(t.r);
        return grey;
    }
};

TEST_F(SamplerTest, WrapModesRepeatMirrorOrClampTheEdge) {
    const SamplerDesc nearest{.label = "nearest", .min = Filter::Nearest, .mag = Filter::Nearest};
    SamplerDesc d = nearest;
    d.wrap = Wrap::Clamp;
    EXPECT_EQ(draw(d, 2), (std::vector{0, 255, 255, 255}));
    d.wrap = Wrap::Repeat;
    EXPECT_EQ(draw(d, 2), (std::vector{0, 255, 0, 255}));
    d.wrap = Wrap::Mirror;
    EXPECT_EQ(draw(d, 2), (std::vector{0, 255, 255, 0}));
}

TEST_F(SamplerTest, LinearFilteringMixesNeighboursAndNearestDoesNot) {
    const std::vector<int> linear = draw({.label = "linear"}, 4);
    const std::vector<double> want{0, 0.25 * 255, 0.75 * 255, 255};
    ASSERT_EQ(linear.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(linear[i], want[i], 1.0) << "pixel " << i;
    EXPECT_EQ(draw({.label = "nearest", .min = Filter::Nearest, .mag = Filter::Nearest}, 4),
              (std::vector{0, 0, 255, 255}));
}

}  // namespace
}  // namespace puddle::gpu
