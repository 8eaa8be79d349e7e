// What the driver can do (gpu/capabilities.hpp): extension lookup matches whole names only, and the
// start-up log line. probe_capabilities itself is checked on a real context in device_test.cpp.
#include "gpu/capabilities.hpp"

#include <gtest/gtest.h>

namespace puddle::gpu {
namespace {

// A name that is the prefix of another ("..._float" of "..._float_linear") must not be taken for it.
TEST(Capabilities, HasMatchesWholeExtensionNamesOnly) {
    Capabilities c;
    c.extensions = "GL_OES_texture_float_linear GL_EXT_color_buffer_half_float GL_KHR_debug";
    EXPECT_TRUE(c.has("GL_OES_texture_float_linear"));     // first
    EXPECT_TRUE(c.has("GL_EXT_color_buffer_half_float"));  // middle
    EXPECT_TRUE(c.has("GL_KHR_debug"));                    // last
    EXPECT_FALSE(c.has("GL_OES_texture_float"));           // a prefix of the first
    EXPECT_FALSE(c.has("GL_EXT_color_buffer_float")) << "a different name sharing words";
    EXPECT_FALSE(c.has("buffer_half_float")) << "a suffix";
    EXPECT_FALSE(c.has("GL_KHR_debu"));
    c.extensions = "GL_EXT_color_buffer_float_x GL_EXT_color_buffer_float";
    EXPECT_TRUE(c.has("GL_EXT_color_buffer_float")) << "found after a longer name that starts with it";
    c.extensions.clear();
    EXPECT_FALSE(c.has("GL_KHR_debug"));
}

TEST(Capabilities, SummaryIsOneLineNamingTheDriverAndEachFeature) {
    Capabilities c;
    c.vendor = "Mesa";
    c.renderer = "llvmpipe";
    c.version = "OpenGL ES 3.2";
    c.float_render_targets = true;
    c.timer_queries = true;
    EXPECT_EQ(
        c.summary(),
        "Mesa / llvmpipe / OpenGL ES 3.2; float targets yes, half-float targets no, float filtering no, "
        "timer queries yes, external images no");
}

}  // namespace
}  // namespace puddle::gpu
