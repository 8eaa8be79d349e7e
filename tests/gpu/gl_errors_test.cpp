// GL errors as values (gpu/gl_errors.hpp): the names messages carry, and which exit code each error means.
// take_gl_error needs a context; device_test.cpp covers it through the Device.
#include "gpu/gl_errors.hpp"

#include <gtest/gtest.h>

#include "gpu/gl.hpp"

namespace puddle::gpu {
namespace {

TEST(GlErrors, NamesEachErrorAndAnUnknownOneInHex) {
    EXPECT_EQ(gl_error_name(GL_NO_ERROR), "GL_NO_ERROR");
    EXPECT_EQ(gl_error_name(GL_INVALID_ENUM), "GL_INVALID_ENUM");
    EXPECT_EQ(gl_error_name(GL_INVALID_VALUE), "GL_INVALID_VALUE");
    EXPECT_EQ(gl_error_name(GL_INVALID_OPERATION), "GL_INVALID_OPERATION");
    EXPECT_EQ(gl_error_name(GL_INVALID_FRAMEBUFFER_OPERATION), "GL_INVALID_FRAMEBUFFER_OPERATION");
    EXPECT_EQ(gl_error_name(GL_OUT_OF_MEMORY), "GL_OUT_OF_MEMORY");
    EXPECT_EQ(gl_error_name(0x0507), "GL error 0x0507");  // GL_CONTEXT_LOST, not in GLES 3.0's list
}

TEST(GlErrors, NamesEachFramebufferStatus) {
    EXPECT_EQ(framebuffer_status_name(GL_FRAMEBUFFER_COMPLETE), "GL_FRAMEBUFFER_COMPLETE");
    EXPECT_EQ(framebuffer_status_name(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT),
              "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT");
    EXPECT_EQ(framebuffer_status_name(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT),
              "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT");
    EXPECT_EQ(framebuffer_status_name(GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS),
              "GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS");
    EXPECT_EQ(framebuffer_status_name(GL_FRAMEBUFFER_UNSUPPORTED), "GL_FRAMEBUFFER_UNSUPPORTED");
    EXPECT_EQ(framebuffer_status_name(GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE),
              "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE");
    EXPECT_EQ(framebuffer_status_name(0), "glCheckFramebufferStatus failed");
    EXPECT_EQ(framebuffer_status_name(0x1234), "framebuffer status 0x1234");
}

// Out of memory may fit at a smaller size (exit code 5, the caller can retry smaller); anything else is a
// runtime error.
TEST(GlErrors, OnlyOutOfMemoryIsTheGpuMemoryExitCode) {
    EXPECT_EQ(exit_code_for(GL_OUT_OF_MEMORY), ExitCode::GpuMemory);
    for (const GLenum e : {GLenum(GL_NO_ERROR), GLenum(GL_INVALID_ENUM), GLenum(GL_INVALID_VALUE),
                           GLenum(GL_INVALID_OPERATION), GLenum(GL_INVALID_FRAMEBUFFER_OPERATION)})
        EXPECT_EQ(exit_code_for(e), ExitCode::Runtime) << gl_error_name(e);
}

}  // namespace
}  // namespace puddle::gpu
