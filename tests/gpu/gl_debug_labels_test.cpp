// Tests for src/gpu/gl_debug_labels.hpp on a real context (KHR_debug on llvmpipe): the label given to a
// texture, sampler, buffer and pipeline through the gpu layer is the object's KHR_debug label exactly, an
// empty label sets none, and a render pass's debug group is pushed once and popped once.
#include "gpu/gl_debug_labels.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "gpu/buffer.hpp"
#include "gpu/device.hpp"
#include "gpu/gl_errors.hpp"
#include "gpu/gl_extensions.hpp"
#include "gpu/render_pass.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::gpu {
namespace {

class GlDebugLabelsTest : public test::DeviceFixture {
protected:
    void SetUp() override {
        test::DeviceFixture::SetUp();
        if (HasFatalFailure()) return;
        // The reading side of KHR_debug; the gpu layer only writes, so it is looked up here.
        get_label_ = reinterpret_cast<PFNGLGETOBJECTLABELKHRPROC>(eglGetProcAddress("glGetObjectLabelKHR"));
        if (!device_->extensions().glObjectLabelKHR || !get_label_)
            GTEST_SKIP() << "this GL has no KHR_debug: labels are no-ops here";
    }
    std::string label_of(GLenum type, GLuint id) {
        char text[256] = {};
        GLsizei length = -1;
        get_label_(type, id, sizeof text, &length, text);
        EXPECT_EQ(take_gl_error(), GLenum(GL_NO_ERROR));
        return std::string(text, std::size_t(std::max(length, 0)));
    }
    static int group_depth() {
        GLint depth = -1;
        glGetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH_KHR, &depth);
        return depth;
    }
    PFNGLGETOBJECTLABELKHRPROC get_label_ = nullptr;
};

TEST_F(GlDebugLabelsTest, EachObjectCarriesItsDescriptorsLabel) {
    const Texture texture =
        device_->create_texture({.label = "sky cube face 3", .width = 4, .height = 4}).value();
    EXPECT_EQ(label_of(GL_TEXTURE, texture.id()), "sky cube face 3");
    const Sampler sampler = device_->create_sampler({.label = "linear clamp"});
    EXPECT_EQ(label_of(GL_SAMPLER_KHR, sampler.id()), "linear clamp");
    const Buffer buffer = device_->create_buffer({.label = "live drops", .size = 64}).value();
    EXPECT_EQ(label_of(GL_BUFFER_KHR, buffer.id()), "live drops");
    const Pipeline pipeline = test::make_copy_pipeline(*device_, Blend::Replace);
    ASSERT_NE(pipeline.id(), 0u);
    EXPECT_EQ(label_of(GL_PROGRAM_KHR, pipeline.id()), "copy");
}

TEST_F(GlDebugLabelsTest, AnEmptyLabelSetsNoneAndALabelIsTakenByLength) {
    const Texture texture = device_->create_texture({.label = "", .width = 1, .height = 1}).value();
    EXPECT_EQ(label_of(GL_TEXTURE, texture.id()), "");
    // A string_view into a longer string: only its own characters become the label.
    const std::string text = "wave field A and more";
    label_object(device_->extensions(), GL_TEXTURE, texture.id(), std::string_view(text).substr(0, 12));
    EXPECT_EQ(label_of(GL_TEXTURE, texture.id()), "wave field A");
}

TEST_F(GlDebugLabelsTest, APassPushesOneGroupAndPopsItOnce) {
    const Texture target = test::make_target(*device_, {4, 4}, {0, 0, 0, 1});
    const int outside = group_depth();
    EXPECT_EQ(outside, 1) << "the default group only";
    {
        RenderPass pass =
            device_->begin_pass({.label = "wave step", .target = {&target, {4, 4}}, .load = LoadOp::Load});
        EXPECT_EQ(group_depth(), outside + 1);
        pass.end();
        EXPECT_EQ(group_depth(), outside);
    }  // the destructor after end() pops nothing more
    EXPECT_EQ(group_depth(), outside);
    EXPECT_EQ(take_gl_error(), GLenum(GL_NO_ERROR)) << "no stack underflow";
    {
        RenderPass pass = device_->begin_pass(
            {.label = "ended by its destructor", .target = {&target, {4, 4}}, .load = LoadOp::Load});
        EXPECT_EQ(group_depth(), outside + 1);
    }
    EXPECT_EQ(group_depth(), outside);
    // push and pop directly, nested.
    push_debug_group(device_->extensions(), "outer");
    push_debug_group(device_->extensions(), "inner");
    EXPECT_EQ(group_depth(), outside + 2);
    pop_debug_group(device_->extensions());
    pop_debug_group(device_->extensions());
    EXPECT_EQ(group_depth(), outside);
    EXPECT_EQ(take_gl_error(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace puddle::gpu
