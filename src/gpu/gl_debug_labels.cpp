#include "gpu/gl_debug_labels.hpp"

namespace puddle::gpu {

void label_object(const GlExtensions& gl, GLenum type, GLuint id, std::string_view text) {
    if (gl.glObjectLabelKHR && !text.empty())
        gl.glObjectLabelKHR(type, id, static_cast<GLsizei>(text.size()), text.data());
}

void push_debug_group(const GlExtensions& gl, std::string_view text) {
    if (gl.glPushDebugGroupKHR)
        gl.glPushDebugGroupKHR(GL_DEBUG_SOURCE_APPLICATION_KHR, 0, static_cast<GLsizei>(text.size()),
                               text.data());
}

void pop_debug_group(const GlExtensions& gl) {
    if (gl.glPopDebugGroupKHR) gl.glPopDebugGroupKHR();
}

}  // namespace puddle::gpu
