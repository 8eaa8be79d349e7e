#include "gpu/debug_labels.hpp"

#include <EGL/egl.h>

namespace puddle::gpu {

void DebugLabels::load() {
    object_label_ = reinterpret_cast<PFNGLOBJECTLABELKHRPROC>(eglGetProcAddress("glObjectLabelKHR"));
    push_group_ = reinterpret_cast<PFNGLPUSHDEBUGGROUPKHRPROC>(eglGetProcAddress("glPushDebugGroupKHR"));
    pop_group_ = reinterpret_cast<PFNGLPOPDEBUGGROUPKHRPROC>(eglGetProcAddress("glPopDebugGroupKHR"));
}

void DebugLabels::label(GLenum type, GLuint id, std::string_view text) const {
    if (object_label_ && !text.empty())
        object_label_(type, id, static_cast<GLsizei>(text.size()), text.data());
}

void DebugLabels::push_group(std::string_view text) const {
    if (push_group_)
        push_group_(GL_DEBUG_SOURCE_APPLICATION_KHR, 0, static_cast<GLsizei>(text.size()), text.data());
}

void DebugLabels::pop_group() const {
    if (pop_group_) pop_group_();
}

}  // namespace puddle::gpu
