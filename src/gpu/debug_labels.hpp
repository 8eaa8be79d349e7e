#pragma once
// KHR_debug labels: object names and pass groups show up in RenderDoc, apitrace and driver messages.
// The entry points are looked up once, when the Device is made; where the extension is missing every
// call is a no-op.

#include <string_view>

#include "gpu/gl.hpp"

namespace puddle::gpu {

class DebugLabels {
public:
    void load();  // call with a current context that has GL_KHR_debug
    void label(GLenum type, GLuint id, std::string_view text) const;
    void push_group(std::string_view text) const;
    void pop_group() const;

private:
    PFNGLOBJECTLABELKHRPROC object_label_ = nullptr;
    PFNGLPUSHDEBUGGROUPKHRPROC push_group_ = nullptr;
    PFNGLPOPDEBUGGROUPKHRPROC pop_group_ = nullptr;
};

}  // namespace puddle::gpu
