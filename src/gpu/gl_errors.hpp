#pragma once
// GL errors as values: what Device::create_* checks after the driver allocates storage. GL records errors
// in sticky flags read by glGetError (GLES 3.0 spec section 2.5), so they are drained before a call and
// read after it, and only that call's error is reported. Private to the gpu layer (its API is GLenum).

#include <string>

#include "gpu/gl.hpp"
#include "util/result.hpp"

namespace puddle::gpu {

// Clears every pending error flag (there can be one per kind); returns the first, GL_NO_ERROR if none.
GLenum take_gl_error();

// "GL_OUT_OF_MEMORY", "GL_INVALID_VALUE", ...; the number in hex for anything else.
std::string gl_error_name(GLenum error);
// "GL_FRAMEBUFFER_UNSUPPORTED", ... (glCheckFramebufferStatus values).
std::string framebuffer_status_name(GLenum status);

// GL_OUT_OF_MEMORY is ExitCode::GpuMemory (smaller sizes may fit); any other GL error is ExitCode::Runtime.
ExitCode exit_code_for(GLenum error);

}  // namespace puddle::gpu
