#include "gpu/gl_extensions.hpp"

#include <cstring>
#include <string>

namespace puddle::gpu {

namespace {

// The extension strings of what is current: GL's is read name by name (glGetString(GL_EXTENSIONS) is
// deprecated in GLES 3), EGL's as one string each.
struct ExtensionLists {
    const char* client = nullptr;
    const char* display = nullptr;
    std::string gl;
};

ExtensionLists current_lists() {
    ExtensionLists lists;
    lists.client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!lists.client) (void)eglGetError();  // EGL_BAD_DISPLAY without EGL_EXT_client_extensions: not ours
    if (const EGLDisplay display = eglGetCurrentDisplay(); display != EGL_NO_DISPLAY)
        lists.display = eglQueryString(display, EGL_EXTENSIONS);
    if (eglGetCurrentContext() != EGL_NO_CONTEXT) {
        GLint n = 0;
        glGetIntegerv(GL_NUM_EXTENSIONS, &n);
        for (GLint i = 0; i < n; ++i)
            if (const auto* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)))) {
                lists.gl += e;
                lists.gl += ' ';
            }
    }
    return lists;
}

template <class Fn>
void look_up(GlExtensions& table, Fn& entry, const char* function, const char* extension, bool advertised) {
    entry = advertised ? reinterpret_cast<Fn>(eglGetProcAddress(function)) : nullptr;
    table.entry_points.push_back({function, extension, entry != nullptr});
}

}  // namespace

bool has_extension(const char* list, const char* name) {
    if (!list || !*name) return false;  // an empty name would match everywhere and never advance
    const std::size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + n, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

GlExtensions GlExtensions::load() {
    const ExtensionLists lists = current_lists();
    GlExtensions t;
    auto client = [&](auto& entry, const char* function, const char* extension) {
        look_up(t, entry, function, extension, has_extension(lists.client, extension));
    };
    auto display = [&](auto& entry, const char* function, const char* extension) {
        look_up(t, entry, function, extension, has_extension(lists.display, extension));
    };
    auto gl = [&](auto& entry, const char* function, const char* extension) {
        look_up(t, entry, function, extension, has_extension(lists.gl.c_str(), extension));
    };
    client(t.eglGetPlatformDisplayEXT, "eglGetPlatformDisplayEXT", "EGL_EXT_platform_base");
    client(t.eglCreatePlatformWindowSurfaceEXT, "eglCreatePlatformWindowSurfaceEXT", "EGL_EXT_platform_base");
    display(t.eglCreateImageKHR, "eglCreateImageKHR", "EGL_KHR_image_base");
    display(t.eglDestroyImageKHR, "eglDestroyImageKHR", "EGL_KHR_image_base");
    gl(t.glEGLImageTargetTexture2DOES, "glEGLImageTargetTexture2DOES", "GL_OES_EGL_image");
    gl(t.glObjectLabelKHR, "glObjectLabelKHR", "GL_KHR_debug");
    gl(t.glPushDebugGroupKHR, "glPushDebugGroupKHR", "GL_KHR_debug");
    gl(t.glPopDebugGroupKHR, "glPopDebugGroupKHR", "GL_KHR_debug");
    return t;
}

}  // namespace puddle::gpu
