// Parameter uniforms are bound once per pipeline (render/param_uniforms.hpp): the shipped shaders bind
// the parameters they read, and a uniform that looks like a parameter's but names none stops the build
// with a message naming the pipeline, the uniform and the nearest parameter.
#include "render/param_uniforms.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "gpu/device.hpp"
#include "platform/display.hpp"

namespace puddle::render {
namespace {

class ParamUniforms : public ::testing::Test {
protected:
    void SetUp() override {
        auto d =
            platform::create_headless_display({.backend = platform::BackendKind::Headless, .size = {32, 32}});
        ASSERT_TRUE(d.ok()) << d.error().message;
        display_ = std::move(d).value();
        device_ = std::make_unique<gpu::Device>();
    }
    void TearDown() override { device_.reset(); }
    bool binds(const ParamBinding& b, std::string_view param) {
        return std::any_of(b.slots.begin(), b.slots.end(), [&](const ParamBinding::Slot& s) {
            return s.decl->name == param && s.location.active();
        });
    }
    std::unique_ptr<platform::Display> display_;
    std::unique_ptr<gpu::Device> device_;
};

TEST_F(ParamUniforms, TheStreetShaderBindsItsParametersAndNothingElse) {
    auto p = device_->create_pipeline({.label = "street", .fragment = "street.frag"});
    ASSERT_TRUE(p.ok()) << p.error().message;
    auto b = bind_params(*p);
    ASSERT_TRUE(b.ok()) << b.error().message;
    EXPECT_TRUE(binds(*b, "street.horizon"));
    EXPECT_TRUE(binds(*b, "street.ripples"));
    EXPECT_FALSE(binds(*b, "water.turbidity")) << "the street does not read the puddle's water";
    for (const auto& s : b->slots) EXPECT_EQ(p->uniform(s.decl->uniform).value, s.location.value);
}

TEST_F(ParamUniforms, TheWaveStepBindsWaveDamping) {
    auto p = device_->create_pipeline({.label = "wave step",
                                       .fragment = "wave_step.frag",
                                       .defines = {"MAX_DROPS 4"},
                                       .textures = {"u_field"},
                                       .uniform_blocks = {"Drops"}});
    ASSERT_TRUE(p.ok()) << p.error().message;
    auto b = bind_params(*p);
    ASSERT_TRUE(b.ok()) << b.error().message;
    EXPECT_TRUE(binds(*b, "wave.damping"));
}

TEST_F(ParamUniforms, AMisspelledParameterUniformIsAnErrorNamingItAndTheNearestParameter) {
    // As if street.frag said u_street_horizn: the shader's uniform is renamed by a #define.
    auto p = device_->create_pipeline(
        {.label = "street", .fragment = "street.frag", .defines = {"u_street_horizon u_street_horizn"}});
    ASSERT_TRUE(p.ok()) << p.error().message;
    auto b = bind_params(*p);
    ASSERT_FALSE(b.ok());
    EXPECT_EQ(
        b.error().message,
        "gpu: pipeline 'street': uniform u_street_horizn is no parameter (did you mean street.horizon?)");
}

}  // namespace
}  // namespace puddle::render
