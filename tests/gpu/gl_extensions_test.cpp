// The extension entry-point table (gpu/gl_extensions.hpp) on a real (surfaceless) context: what Mesa
// offers is loaded, every loaded entry's extension is advertised, and nothing is loaded for an
// extension that is not there.
#include "gpu/gl_extensions.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <thread>

#include "gpu/device.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::gpu {
namespace {

class GlExtensionsTest : public test::DeviceFixture {};

// The context's GL extensions, read here independently of the table.
bool gl_advertises(const char* name) {
    GLint n = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; ++i)
        if (const auto* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i))))
            if (std::strcmp(e, name) == 0) return true;
    return false;
}

bool egl_advertises(const char* name) {
    return has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), name) ||
           has_extension(eglQueryString(eglGetCurrentDisplay(), EGL_EXTENSIONS), name);
}

bool advertised(const char* extension) {
    return std::strncmp(extension, "GL_", 3) == 0 ? gl_advertises(extension) : egl_advertises(extension);
}

TEST_F(GlExtensionsTest, HasWhatMesaOffers) {
    const GlExtensions& gl = device_->extensions();
    ASSERT_TRUE(gl_advertises("GL_KHR_debug")) << "llvmpipe offers KHR_debug";
    EXPECT_NE(gl.glObjectLabelKHR, nullptr);
    EXPECT_NE(gl.glPushDebugGroupKHR, nullptr);
    EXPECT_NE(gl.glPopDebugGroupKHR, nullptr);
    ASSERT_TRUE(gl_advertises("GL_OES_EGL_image_external")) << "llvmpipe offers OES_EGL_image_external";
    EXPECT_NE(gl.glEGLImageTargetTexture2DOES, nullptr);
    ASSERT_TRUE(egl_advertises("EGL_KHR_image_base"));
    EXPECT_NE(gl.eglCreateImageKHR, nullptr);
    EXPECT_NE(gl.eglDestroyImageKHR, nullptr);
    ASSERT_TRUE(egl_advertises("EGL_EXT_platform_base"));
    EXPECT_NE(gl.eglGetPlatformDisplayEXT, nullptr);
    EXPECT_NE(gl.eglCreatePlatformWindowSurfaceEXT, nullptr);
}

TEST_F(GlExtensionsTest, EveryLoadedEntryIsAdvertised) {
    const GlExtensions& gl = device_->extensions();
    ASSERT_EQ(gl.entry_points.size(), 8u) << "one line per member of GlExtensions";
    for (const GlExtensions::EntryPoint& e : gl.entry_points) {
        if (e.loaded)
            EXPECT_TRUE(advertised(e.extension)) << e.function << " loaded without " << e.extension;
        else
            EXPECT_FALSE(advertised(e.extension))
                << e.function << " missing although " << e.extension << " is there";
    }
}

TEST_F(GlExtensionsTest, NothingCurrentLoadsOnlyClientEntries) {
    // A thread starts with no display or context current (EGL 1.5 section 3.7.3): GL and display
    // extensions are unknown there, so their entries stay null although eglGetProcAddress would
    // return pointers for them.
    GlExtensions bare;
    std::thread([&] { bare = GlExtensions::load(); }).join();
    EXPECT_NE(bare.eglGetPlatformDisplayEXT, nullptr);
    EXPECT_EQ(bare.eglCreateImageKHR, nullptr);
    EXPECT_EQ(bare.glEGLImageTargetTexture2DOES, nullptr);
    EXPECT_EQ(bare.glObjectLabelKHR, nullptr);
    EXPECT_NE(eglGetProcAddress("glObjectLabelKHR"), nullptr) << "the lookup alone does not tell support";
    for (const GlExtensions::EntryPoint& e : bare.entry_points)
        EXPECT_EQ(e.loaded, std::strcmp(e.extension, "EGL_EXT_platform_base") == 0) << e.function;
}

TEST(GlExtensionNames, WholeWordsOnly) {
    EXPECT_TRUE(has_extension("GL_KHR_debug GL_OES_EGL_image", "GL_OES_EGL_image"));
    EXPECT_TRUE(has_extension("GL_OES_EGL_image_external GL_OES_EGL_image", "GL_OES_EGL_image"))
        << "found after a longer name that starts with it";
    EXPECT_FALSE(has_extension("GL_OES_EGL_image_external", "GL_OES_EGL_image"));
    EXPECT_FALSE(has_extension("GL_KHR_debug", "GL_KHR_debu"));
    EXPECT_FALSE(has_extension(nullptr, "GL_KHR_debug"));
    EXPECT_FALSE(has_extension("GL_KHR_debug", "")) << "an empty name is no extension (and ends the search)";
}

}  // namespace
}  // namespace puddle::gpu
