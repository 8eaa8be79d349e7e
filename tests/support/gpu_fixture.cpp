#include "support/gpu_fixture.hpp"

#include <algorithm>

#include "params/config_loader.hpp"

namespace puddle::test {

params::Params make_params(std::initializer_list<std::string> sets) {
    params::Params p;
    apply_sets(p, sets);
    return p;
}

void apply_sets(params::Params& params, const std::vector<std::string>& sets) {
    for (const std::string& s : sets) {
        auto e = params::parse_assignment(s);
        EXPECT_TRUE(e.ok()) << s << ": " << (e.ok() ? "" : e.error().message);
        if (e) params.set(e->id, e->value, params::ParamSource::CommandLine);
    }
}

std::unique_ptr<app::Engine> make_engine(const params::Params& params, glm::ivec2 size,
                                         const gpu::DeviceOptions& device) {
    platform::DisplayOptions display;
    display.backend = platform::BackendKind::Headless;
    display.size = size;
    auto engine = app::Engine::create(params, display, device, {systems::add_puddle_plugin});
    EXPECT_TRUE(engine.ok()) << (engine.ok() ? "" : engine.error().message);
    if (!engine) return nullptr;
    return std::move(engine).value();
}

assets::Image render_frames(app::Engine& engine, int frames, double dt) {
    for (int i = 0; i < frames; ++i) {
        auto r = engine.frame(dt);
        EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    }
    return engine.read_frame();
}

void DeviceFixture::SetUp() {
    auto d =
        platform::create_headless_display({.backend = platform::BackendKind::Headless, .size = {64, 32}});
    ASSERT_TRUE(d.ok()) << d.error().message;
    display_ = std::move(d).value();
    device_ = std::make_unique<gpu::Device>();
}

void DeviceFixture::TearDown() {
    device_.reset();
}

gpu::Texture make_target(gpu::Device& device, glm::ivec2 size, glm::vec4 clear) {
    auto t = device.create_texture({.label = "test target",
                                    .format = gpu::TextureFormat::RGBA8,
                                    .width = size.x,
                                    .height = size.y,
                                    .render_target = true});
    EXPECT_TRUE(t.ok()) << (t.ok() ? "" : t.error().message);
    if (!t) return {};
    device.begin_pass({.label = "fill", .target = {&*t, size}, .load = gpu::LoadOp::Clear, .clear = clear});
    return std::move(t).value();
}

gpu::Texture make_texels(gpu::Device& device, const std::vector<glm::u8vec4>& texels) {
    auto t = device.create_texture({.label = "test texels",
                                    .format = gpu::TextureFormat::RGBA8,
                                    .width = static_cast<int>(texels.size()),
                                    .height = 1});
    EXPECT_TRUE(t.ok()) << (t.ok() ? "" : t.error().message);
    if (!t) return {};
    t->upload(std::as_bytes(std::span(texels)));
    return std::move(t).value();
}

gpu::Pipeline make_copy_pipeline(gpu::Device& device, gpu::Blend blend) {
    auto p = device.create_pipeline({.label = "copy",
                                     .fragment = "output_canvas.frag",
                                     .defines = {"SCALED"},
                                     .textures = {"u_canvas"},
                                     .blend = blend});
    EXPECT_TRUE(p.ok()) << (p.ok() ? "" : p.error().message);
    return p ? std::move(p).value() : gpu::Pipeline();
}

void draw_texture(gpu::Device& device, const gpu::Texture& target, const gpu::Pipeline& pipeline,
                  const gpu::Texture& texture) {
    const gpu::Sampler nearest =
        device.create_sampler({.label = "nearest", .min = gpu::Filter::Nearest, .mag = gpu::Filter::Nearest});
    const glm::ivec2 size{target.width(), target.height()};
    device.begin_pass({.label = "draw texture", .target = {&target, size}, .load = gpu::LoadOp::Load})
        .set_pipeline(pipeline)
        .set_texture(0, texture, nearest)
        .set("u_quarter_turns", 0)
        .set("u_screen_size", glm::vec2(size))
        .set("u_brightness", 1.0f)  // the canvas shader dims by display.brightness; a copy keeps the texels
        .draw_fullscreen();
}

std::vector<glm::u8vec4> read_texels(gpu::Device& device, const gpu::Texture& texture, int level) {
    const glm::ivec2 size{std::max(1, texture.width() >> level), std::max(1, texture.height() >> level)};
    std::vector<glm::u8vec4> texels(std::size_t(size.x) * std::size_t(size.y));
    device.read_pixels({.texture = &texture, .size = size, .level = level},
                       std::span(reinterpret_cast<std::uint8_t*>(texels.data()), texels.size() * 4));
    return texels;
}

}  // namespace puddle::test
