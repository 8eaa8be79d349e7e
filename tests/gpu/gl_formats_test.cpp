// Tests for src/gpu/gl_formats.hpp: each TextureFormat is stored and uploaded with the internal format,
// format and type that GLES 3.0 (spec tables 3.2 and 3.13) pairs it with, and the upload's layout agrees
// with the texel size. The expected rows are copied from the spec, not from the code.
#include "gpu/gl_formats.hpp"

#include <gtest/gtest.h>

#include <string>

namespace puddle::gpu {
namespace {

struct SpecRow {
    TextureFormat format;
    GLenum internal, pixel_format, type;
    int stored_bits;  // table 3.13: the sized internal format's bits per texel
};

// GLES 3.0.6, table 3.2 (valid internal format, format and type combinations) and table 3.13 (sizes).
const SpecRow spec_rows[] = {
    {TextureFormat::RGBA8, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 32},
    {TextureFormat::SRGB8_A8, GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, 32},
    {TextureFormat::RG32F, GL_RG32F, GL_RG, GL_FLOAT, 64},
    {TextureFormat::RG32I, GL_RG32I, GL_RG_INTEGER, GL_INT, 64},
    {TextureFormat::RGBA16F, GL_RGBA16F, GL_RGBA, GL_FLOAT, 64},  // table 3.2 also allows GL_HALF_FLOAT
    {TextureFormat::RGBA32F, GL_RGBA32F, GL_RGBA, GL_FLOAT, 128},
    {TextureFormat::RGBA32I, GL_RGBA32I, GL_RGBA_INTEGER, GL_INT, 128},
    {TextureFormat::R8, GL_R8, GL_RED, GL_UNSIGNED_BYTE, 8},
    {TextureFormat::RG8, GL_RG8, GL_RG, GL_UNSIGNED_BYTE, 16},
};

// Components per pixel of an upload's format, and bytes per component of its type (spec tables 3.3, 3.4).
int components(GLenum format) {
    switch (format) {
        case GL_RED:
            return 1;
        case GL_RG:
        case GL_RG_INTEGER:
            return 2;
        case GL_RGBA:
        case GL_RGBA_INTEGER:
            return 4;
    }
    return 0;
}
int type_bytes(GLenum type) {
    switch (type) {
        case GL_UNSIGNED_BYTE:
            return 1;
        case GL_HALF_FLOAT:
            return 2;
        case GL_FLOAT:
        case GL_INT:
            return 4;
    }
    return 0;
}

TEST(GlFormats, EveryFormatHasItsSpecRow) {
    // format_name names every enumerator and says "?" past the last one: nine formats, nine rows.
    constexpr int formats = static_cast<int>(std::size(spec_rows));
    for (int f = 0; f < formats; ++f) EXPECT_NE(std::string(format_name(TextureFormat(f))), "?") << f;
    EXPECT_EQ(std::string(format_name(TextureFormat(formats))), "?") << "a format without a row here";
    for (int f = 0; f < formats; ++f) EXPECT_EQ(int(spec_rows[f].format), f) << "rows in enum order";
}

TEST(GlFormats, EachFormatIsThePairTheSpecGives) {
    for (const SpecRow& row : spec_rows) {
        SCOPED_TRACE(format_name(row.format));
        const GlFormat gl = gl_format(row.format);
        EXPECT_EQ(gl.internal, row.internal);
        EXPECT_EQ(gl.format, row.pixel_format);
        EXPECT_EQ(gl.type, row.type);
    }
}

TEST(GlFormats, TheUploadLayoutAndTheTexelSizeAgree) {
    for (const SpecRow& row : spec_rows) {
        SCOPED_TRACE(format_name(row.format));
        const GlFormat gl = gl_format(row.format);
        EXPECT_EQ(gl.channels, components(gl.format)) << "values per texel in an upload";
        EXPECT_EQ(gl.bytes_per_channel, type_bytes(gl.type)) << "bytes per value in an upload";
        EXPECT_EQ(bytes_per_texel(row.format) * 8, row.stored_bits) << "as stored (table 3.13)";
    }
}

}  // namespace
}  // namespace puddle::gpu
