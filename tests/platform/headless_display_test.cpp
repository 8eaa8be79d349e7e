// The headless backend: surfaceless EGL, an offscreen target of the requested size.
#include <gtest/gtest.h>

#include "gpu/device.hpp"
#include "platform/display.hpp"

namespace puddle::platform {
namespace {

TEST(HeadlessDisplay, OffscreenTargetHasTheRequestedSize) {
    auto d = create_headless_display({.backend = BackendKind::Headless, .size = {100, 50}});
    ASSERT_TRUE(d.ok()) << d.error().message;
    gpu::Device device;
    (*d)->prepare(device);
    const gpu::FrameTarget t = (*d)->frame_target();
    ASSERT_NE(t.texture, nullptr);
    EXPECT_EQ(t.size, glm::ivec2(100, 50));
    EXPECT_EQ(t.texture->width(), 100);
    EXPECT_EQ((*d)->kind(), BackendKind::Headless);
    EXPECT_NE((*d)->describe().find("surfaceless"), std::string::npos);
    EXPECT_TRUE((*d)->present().ok());
}

TEST(HeadlessDisplay, DefaultSizeIs640x360) {
    auto d = create_headless_display({.backend = BackendKind::Headless});
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_EQ((*d)->size(), glm::ivec2(640, 360));
}

}  // namespace
}  // namespace puddle::platform
