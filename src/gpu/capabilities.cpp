#include "gpu/capabilities.hpp"

#include <fmt/format.h>

#include <cstring>

#include "gpu/gl.hpp"

namespace puddle::gpu {

namespace {
std::string gl_string(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "";
}
}  // namespace

bool Capabilities::has(const char* extension) const {
    const std::size_t n = std::strlen(extension);
    std::size_t pos = 0;
    while ((pos = extensions.find(extension, pos)) != std::string::npos) {
        if ((pos == 0 || extensions[pos - 1] == ' ') &&
            (pos + n == extensions.size() || extensions[pos + n] == ' '))
            return true;
        pos += n;
    }
    return false;
}

Capabilities probe_capabilities(bool forbid_float_targets) {
    Capabilities c;
    c.vendor = gl_string(GL_VENDOR);
    c.renderer = gl_string(GL_RENDERER);
    c.version = gl_string(GL_VERSION);
    c.glsl_version = gl_string(GL_SHADING_LANGUAGE_VERSION);
    glGetIntegerv(GL_MAJOR_VERSION, &c.major);
    glGetIntegerv(GL_MINOR_VERSION, &c.minor);
    GLint n = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; ++i) {
        if (const auto* e =
                reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)))) {
            if (!c.extensions.empty()) c.extensions += ' ';
            c.extensions += e;
        }
    }
    const bool es32 = c.major > 3 || (c.major == 3 && c.minor >= 2);  // EXT_color_buffer_float is core in 3.2
    c.float_render_targets = !forbid_float_targets && (es32 || c.has("GL_EXT_color_buffer_float"));
    c.half_float_render_targets =
        !forbid_float_targets && (c.float_render_targets || c.has("GL_EXT_color_buffer_half_float"));
    c.float_linear_filtering = c.has("GL_OES_texture_float_linear");
    c.timer_queries = c.has("GL_EXT_disjoint_timer_query");
    c.external_images = c.has("GL_OES_EGL_image_external_essl3");
    c.debug_labels = c.has("GL_KHR_debug");
    c.anisotropic_filtering = c.has("GL_EXT_texture_filter_anisotropic");
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &c.max_texture_size);
    glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &c.max_cube_map_size);
    if (c.anisotropic_filtering) glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &c.max_anisotropy);
    return c;
}

std::string Capabilities::summary() const {
    auto yn = [](bool b) { return b ? "yes" : "no"; };
    return fmt::format(
        "{} / {} / {}; float targets {}, half-float targets {}, float filtering {}, "
        "timer queries {}, external images {}",
        vendor, renderer, version, yn(float_render_targets), yn(half_float_render_targets),
        yn(float_linear_filtering), yn(timer_queries), yn(external_images));
}

}  // namespace puddle::gpu
