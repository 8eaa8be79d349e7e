#pragma once
// KHR_debug labels: object names and pass groups show up in RenderDoc, apitrace and driver messages.
// The entry points come from the Device's extension table (gpu/gl_extensions.hpp); where the extension
// is missing every call is a no-op. Private to the gpu layer.

#include <string_view>

#include "gpu/gl.hpp"
#include "gpu/gl_extensions.hpp"

namespace puddle::gpu {

// `type` is the KHR_debug identifier (GL_TEXTURE, GL_PROGRAM_KHR, ...); an empty text sets no label.
void label_object(const GlExtensions& gl, GLenum type, GLuint id, std::string_view text);
void push_debug_group(const GlExtensions& gl, std::string_view text);
void pop_debug_group(const GlExtensions& gl);

}  // namespace puddle::gpu
