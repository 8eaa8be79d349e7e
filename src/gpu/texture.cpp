#include "gpu/texture.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>

#include "gpu/gl.hpp"
#include "gpu/gl_formats.hpp"

namespace puddle::gpu {

namespace detail {
void delete_texture(std::uint32_t id) {
    glDeleteTextures(1, &id);
}
void delete_framebuffer(std::uint32_t id) {
    glDeleteFramebuffers(1, &id);
}
void delete_sampler(std::uint32_t id) {
    glDeleteSamplers(1, &id);
}
}  // namespace detail

const char* format_name(TextureFormat f) {
    switch (f) {
        case TextureFormat::RGBA8:
            return "RGBA8";
        case TextureFormat::SRGB8_A8:
            return "SRGB8_ALPHA8";
        case TextureFormat::RG32F:
            return "RG32F";
        case TextureFormat::RG32I:
            return "RG32I";
        case TextureFormat::RGBA16F:
            return "RGBA16F";
        case TextureFormat::RGBA32F:
            return "RGBA32F";
        case TextureFormat::RGBA32I:
            return "RGBA32I";
        case TextureFormat::R8:
            return "R8";
        case TextureFormat::RG8:
            return "RG8";
    }
    return "?";
}

int bytes_per_texel(TextureFormat f) {
    switch (f) {
        case TextureFormat::RGBA8:
        case TextureFormat::SRGB8_A8:
            return 4;
        case TextureFormat::RG32F:
        case TextureFormat::RG32I:
        case TextureFormat::RGBA16F:
            return 8;
        case TextureFormat::RGBA32F:
        case TextureFormat::RGBA32I:
            return 16;
        case TextureFormat::R8:
            return 1;
        case TextureFormat::RG8:
            return 2;
    }
    return 4;
}

std::uint64_t storage_bytes(const TextureDesc& desc) {
    std::uint64_t bytes = 0;
    for (int level = 0; level < std::max(1, desc.mip_levels) && level < 32; ++level) {
        const auto w = static_cast<std::uint64_t>(std::max(1, desc.width >> level));
        const auto h = static_cast<std::uint64_t>(std::max(1, desc.height >> level));
        bytes += w * h * static_cast<std::uint64_t>(bytes_per_texel(desc.format));
    }
    return desc.kind == TextureKind::Cube ? bytes * 6 : bytes;
}

std::string describe_storage(const TextureDesc& desc) {
    const char* kind = desc.kind == TextureKind::Cube       ? "cube 6 x "
                       : desc.kind == TextureKind::External ? "external "
                                                            : "";
    const std::uint64_t bytes = storage_bytes(desc);
    const std::string amount = bytes < (1u << 20)
                                   ? fmt::format("{} bytes", bytes)
                                   : fmt::format("{:.1f} MiB", static_cast<double>(bytes) / (1 << 20));
    return fmt::format("{}{}x{} {}, {} level{}, {}", kind, desc.width, desc.height, format_name(desc.format),
                       desc.mip_levels, desc.mip_levels == 1 ? "" : "s", amount);
}

void Texture::upload(std::span<const std::byte> data, int level, int face) {
    upload_rows(data, level, face, 0, std::max(1, desc_.height >> level));
}

void Texture::upload_rows(std::span<const std::byte> data, int level, int face, int first_row, int rows) {
    const GlFormat f = gl_format(desc_.format);
    const int w = std::max(1, desc_.width >> level), h = std::max(1, desc_.height >> level);
    assert(first_row >= 0 && rows >= 0 && first_row + rows <= h);
    assert(data.size() >= std::size_t(w) * rows * f.channels * f.bytes_per_channel);
    (void)h;
    (void)data;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (desc_.kind == TextureKind::Cube) {
        glBindTexture(GL_TEXTURE_CUBE_MAP, id());
        glTexSubImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), level, 0, first_row, w, rows, f.format,
                        f.type, data.data());
    } else {
        glBindTexture(GL_TEXTURE_2D, id());
        glTexSubImage2D(GL_TEXTURE_2D, level, 0, first_row, w, rows, f.format, f.type, data.data());
    }
}

void Texture::upload_rows(std::span<const std::byte> data, int row_bytes) {
    const GlFormat f = gl_format(desc_.format);
    const int texel = f.channels * f.bytes_per_channel;
    assert(desc_.kind == TextureKind::D2 && row_bytes % texel == 0);
    assert(data.size() >= std::size_t(row_bytes) * (desc_.height - 1) + std::size_t(desc_.width) * texel);
    (void)data;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, row_bytes / texel);
    glBindTexture(GL_TEXTURE_2D, id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, desc_.width, desc_.height, f.format, f.type, data.data());
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

void Texture::generate_mipmaps() {
    const GLenum target = desc_.kind == TextureKind::Cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    glBindTexture(target, id());
    glGenerateMipmap(target);
}

std::uint32_t Texture::framebuffer(int face, int level) const {
    const bool cube = desc_.kind == TextureKind::Cube;
    const std::size_t slot = static_cast<std::size_t>(cube ? face : 0);
    auto& fbo = fbos_[slot];
    if (fbo && fbo_levels_[slot] == level) return fbo.get();
    if (!fbo) {
        GLuint id_fbo = 0;
        glGenFramebuffers(1, &id_fbo);
        fbo = GlHandle<detail::delete_framebuffer>(id_fbo);
    }
    // Another level re-attaches (mip levels are rendered once, at load; frames use level 0).
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.get());
    const GLenum target = cube ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face) : GL_TEXTURE_2D;
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, id(), level);
    fbo_levels_[slot] = level;
    return fbo.get();
}

}  // namespace puddle::gpu
