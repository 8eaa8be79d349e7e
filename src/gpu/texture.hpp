#pragma once
// Textures and samplers: move-only owners made by Device::create_texture / create_sampler.
// create_texture checks what the driver made (storage, and the framebuffer of a render target) and
// returns an error naming the texture, its size and the GL error instead of an empty texture.

#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <string>

#include "gpu/handle.hpp"

namespace puddle::gpu {

enum class TextureFormat {
    RGBA8,     // linear 8-bit colour, data
    SRGB8_A8,  // 8-bit sRGB colour: the sampler decodes to linear
    RG32F,     // wave field (height, previous height)
    RG32I,     // wave field, fixed point, where float targets are missing
    RGBA16F,   // filterable float: surface (height + normal), HDR colour
    RGBA32F,
    RGBA32I,  // four ints: tables of floats as bits (the rain cells), renderable wherever GLES 3 is
    R8,       // one 8-bit channel: a camera's Y plane
    RG8,      // two 8-bit channels: a camera's interleaved UV plane
};
// External: a GL_TEXTURE_EXTERNAL_OES over an EGLImage (camera dmabufs), made by create_external_image.
enum class TextureKind { D2, Cube, External };

struct TextureDesc {
    std::string label;
    TextureKind kind = TextureKind::D2;
    TextureFormat format = TextureFormat::RGBA8;
    int width = 1, height = 1;
    int mip_levels = 1;
    // Passes render into it (wgpu's RENDER_ATTACHMENT usage): create_texture checks that its level 0
    // framebuffer is complete, so an unrenderable format fails at creation, not as a black frame.
    bool render_target = false;
};

// Levels of a full mip chain for a largest side of `size` texels: floor(log2(size)) + 1, down to 1x1
// (GLES 3.2 section 8.14.3, "Mipmapping"); 1 for sizes below 1.
inline int full_mip_count(int size) {
    return std::bit_width(static_cast<unsigned>(size < 1 ? 1 : size));
}

// Bytes of GPU storage the texture asks for: every level, every face (the driver may pad).
std::uint64_t storage_bytes(const TextureDesc& desc);
// "cube 6 x 4096x4096 SRGB8_ALPHA8, 13 levels, 512.0 MiB" (under 1 MiB in bytes): what an error message
// says was asked for.
std::string describe_storage(const TextureDesc& desc);

namespace detail {
void delete_texture(std::uint32_t id);
void delete_framebuffer(std::uint32_t id);
void delete_sampler(std::uint32_t id);
}  // namespace detail

class Texture {
public:
    Texture() = default;
    const TextureDesc& desc() const { return desc_; }
    int width() const { return desc_.width; }
    int height() const { return desc_.height; }
    std::uint32_t id() const { return id_.get(); }  // the GL texture name, for tests and interop
    explicit operator bool() const { return static_cast<bool>(id_); }

    // Uploads a whole level (face: 0..5 for cube maps, GL order +X,-X,+Y,-Y,+Z,-Z). The data layout follows
    // the format: RGBA8/SRGB8_A8 bytes RGBA; float formats floats with the format's channel count
    // (RGBA16F also takes RGBA floats); RG32I ints. Rows bottom-up in GL terms = top-first image rows
    // for cube faces (GL's cube convention), first row at t=0 for 2D.
    void upload(std::span<const std::byte> data, int level = 0, int face = 0);
    // Uploads `rows` rows of a level from `first_row` on (`data` holds just those rows, laid out as for
    // upload()): a large level in several calls, so no single call holds up a frame for long.
    void upload_rows(std::span<const std::byte> data, int level, int face, int first_row, int rows);
    // Level 0 of a 2D texture from rows `row_bytes` apart (a driver's bytesperline, often padded).
    void upload_rows(std::span<const std::byte> data, int row_bytes);
    void generate_mipmaps();
    // The GL framebuffer name that renders into a level (of one face for cube maps), made on first use.
    std::uint32_t framebuffer(int face = 0, int level = 0) const;

private:
    friend class Device;
    friend class ExternalImage;
    TextureDesc desc_;
    GlHandle<detail::delete_texture> id_;
    mutable std::array<GlHandle<detail::delete_framebuffer>, 6> fbos_;  // one per cube face
    mutable std::array<int, 6> fbo_levels_{};                           // the level each one holds
};

enum class Filter { Nearest, Linear };
enum class Wrap { Clamp, Repeat, Mirror };

struct SamplerDesc {
    std::string label;
    Filter min = Filter::Linear, mag = Filter::Linear;
    bool mipmaps = false;  // trilinear when min is Linear
    Wrap wrap = Wrap::Clamp;
    float anisotropy = 1.0f;  // clamped to the device's maximum; ignored without the extension
};

class Sampler {
public:
    Sampler() = default;
    std::uint32_t id() const { return id_.get(); }  // the GL sampler name

private:
    friend class Device;
    GlHandle<detail::delete_sampler> id_;
};

const char* format_name(TextureFormat f);
// Bytes per texel as stored (RGBA16F is 8, although it uploads from floats).
int bytes_per_texel(TextureFormat f);

}  // namespace puddle::gpu
