#include "gpu/gl_formats.hpp"

namespace puddle::gpu {

GlFormat gl_format(TextureFormat f) {
    switch (f) {
        case TextureFormat::RGBA8:
            return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 1};
        case TextureFormat::SRGB8_A8:
            return {GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 1};
        case TextureFormat::RG32F:
            return {GL_RG32F, GL_RG, GL_FLOAT, 2, 4};
        case TextureFormat::RG32I:
            return {GL_RG32I, GL_RG_INTEGER, GL_INT, 2, 4};
        case TextureFormat::RGBA16F:
            return {GL_RGBA16F, GL_RGBA, GL_FLOAT, 4, 4};
        case TextureFormat::RGBA32F:
            return {GL_RGBA32F, GL_RGBA, GL_FLOAT, 4, 4};
        case TextureFormat::RGBA32I:
            return {GL_RGBA32I, GL_RGBA_INTEGER, GL_INT, 4, 4};
        case TextureFormat::R8:
            return {GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, 1};
        case TextureFormat::RG8:
            return {GL_RG8, GL_RG, GL_UNSIGNED_BYTE, 2, 1};
    }
    return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 1};
}

}  // namespace puddle::gpu
