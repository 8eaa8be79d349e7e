#pragma once
// The GL side of each TextureFormat: what glTexStorage2D and glTexSubImage2D are called with (GLES 3.0
// spec tables 3.2 and 3.13). Private to the gpu layer: only src/gpu/*.cpp, src/platform and the gpu
// tests include it.

#include "gpu/gl.hpp"
#include "gpu/texture.hpp"

namespace puddle::gpu {

// GL internal format, pixel format and type for uploads of each TextureFormat, and the upload's layout:
// `channels` values of `bytes_per_channel` bytes per texel.
struct GlFormat {
    GLenum internal, format, type;
    int channels;
    int bytes_per_channel;
};
GlFormat gl_format(TextureFormat f);

}  // namespace puddle::gpu
