#pragma once
// Every GL and EGL extension entry point Puddle calls, looked up once into one table (as kmscube's
// `struct egl` does). Private to the gpu layer: only src/gpu/*.cpp and src/platform include it.
//
// An entry is set only when its extension is advertised: a driver's eglGetProcAddress may return a
// pointer for a function it does not support (EGL 1.5 section 3.10), so a non-null entry is the test of
// support. Client EGL extensions need nothing current; display extensions are the current display's,
// GL extensions the current context's. The Device loads its table once, when it is made.

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <vector>

#include "gpu/gl.hpp"

namespace puddle::gpu {

struct GlExtensions {
    // EGL_EXT_platform_base (client extension): displays and window surfaces for a chosen platform.
    PFNEGLGETPLATFORMDISPLAYEXTPROC eglGetPlatformDisplayEXT = nullptr;
    PFNEGLCREATEPLATFORMWINDOWSURFACEEXTPROC eglCreatePlatformWindowSurfaceEXT = nullptr;
    // EGL_KHR_image_base (display extension): EGLImages from dmabufs and GL textures.
    PFNEGLCREATEIMAGEKHRPROC eglCreateImageKHR = nullptr;
    PFNEGLDESTROYIMAGEKHRPROC eglDestroyImageKHR = nullptr;
    // GL_OES_EGL_image: an EGLImage as a texture's storage (GL_OES_EGL_image_external adds the target).
    PFNGLEGLIMAGETARGETTEXTURE2DOESPROC glEGLImageTargetTexture2DOES = nullptr;
    // GL_KHR_debug: object labels and pass groups for RenderDoc, apitrace and driver messages.
    PFNGLOBJECTLABELKHRPROC glObjectLabelKHR = nullptr;
    PFNGLPUSHDEBUGGROUPKHRPROC glPushDebugGroupKHR = nullptr;
    PFNGLPOPDEBUGGROUPKHRPROC glPopDebugGroupKHR = nullptr;

    // What load() looked up, in the order above: the function, its extension, and whether it was set.
    struct EntryPoint {
        const char* function;
        const char* extension;
        bool loaded;
    };
    std::vector<EntryPoint> entry_points;

    // Looks every entry up for what is current on the calling thread (see above); call it once per
    // context. Never fails: a missing extension leaves its entries null.
    static GlExtensions load();
};

// Whether the space-separated `list` (an extension string) holds `name` as a whole word; false for a null
// list or an empty name.
bool has_extension(const char* list, const char* name);

}  // namespace puddle::gpu
