#include "support/gpu_fixture.hpp"

#include "params/config_loader.hpp"

namespace puddle::test {

params::Params make_params(std::initializer_list<std::string> sets) {
    params::Params p;
    for (const std::string& s : sets) {
        auto e = params::parse_assignment(s);
        EXPECT_TRUE(e.ok()) << (e.ok() ? "" : e.error().message);
        if (e) p.set(e->id, e->value, params::ParamSource::CommandLine);
    }
    return p;
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

}  // namespace puddle::test
