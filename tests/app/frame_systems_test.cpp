// Tests for systems/display/display_plugin.hpp: on a real headless engine, the capture system reads the frame
// back only when asked and gives exactly the pixels drawn, top row first; systems::PresentStatus holds what
// the last present returned.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <deque>
#include <string>

#include "app/engine.hpp"
#include "gpu/render_pass.hpp"
#include "support/test_support.hpp"
#include "systems/display/display_plugin.hpp"
#include "systems/puddle/puddle_plugin.hpp"

namespace puddle::app {
namespace {

using Rgba8 = std::array<std::uint8_t, 4>;

// Resource of the test plugin: the colours of the target's top and bottom halves. Whole multiples of
// 1/255, so that the 8-bit read-back is exact.
struct Halves {
    Rgba8 top{0, 0, 0, 255};
    Rgba8 bottom{0, 0, 0, 255};
};

glm::vec4 to_float(Rgba8 c) {
    return glm::vec4(c[0], c[1], c[2], c[3]) / 255.0f;
}

// Clears the whole target to the bottom colour, then the upper rows to the top colour. A pass's rows count
// from GL's bottom row, so the upper half is rows [h - h/2, h).
void draw_halves_system(gpu::Device& device, const systems::RenderTarget& target, const Halves& halves) {
    const int h = target.target.size.y;
    device.begin_pass({.label = "bottom half",
                       .target = target.target,
                       .load = gpu::LoadOp::Clear,
                       .clear = to_float(halves.bottom)});
    device.begin_pass({.label = "top half",
                       .target = target.target,
                       .load = gpu::LoadOp::Clear,
                       .clear = to_float(halves.top),
                       .rows = {h - h / 2, h / 2}});
}

Result<void> add_halves_plugin(ecs::World& world, ecs::Schedule& schedule) {
    world.insert_resource<Halves>();
    schedule.add(ecs::Stage::Render, "halves", draw_halves_system);
    return {};
}

std::unique_ptr<Engine> halves_engine(glm::ivec2 size) {
    platform::DisplayOptions display;
    display.backend = platform::BackendKind::Headless;
    display.size = size;
    auto engine = Engine::create(params::Params{}, display, {}, {add_halves_plugin});
    if (!engine.ok()) ADD_FAILURE() << engine.error().message;
    return engine.ok() ? std::move(*engine) : nullptr;
}

Rgba8 pixel(const assets::Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel8(x, y);
    return {p[0], p[1], p[2], p[3]};
}

// Counts the pixels of rows [first, last) that are not `expected`; the first one is reported.
int pixels_not(const assets::Image& image, int first, int last, Rgba8 expected) {
    int wrong = 0;
    for (int y = first; y < last; ++y)
        for (int x = 0; x < image.width; ++x)
            if (pixel(image, x, y) != expected && wrong++ == 0)
                ADD_FAILURE() << "pixel (" << x << ", " << y << ") is " << int(pixel(image, x, y)[0]) << ","
                              << int(pixel(image, x, y)[1]) << "," << int(pixel(image, x, y)[2]) << ","
                              << int(pixel(image, x, y)[3]) << ", expected " << int(expected[0]) << ","
                              << int(expected[1]) << "," << int(expected[2]) << "," << int(expected[3]);
    return wrong;
}

TEST(FrameSystems, TheCaptureIsTheDrawnPixelsTopRowFirst) {
    auto engine = halves_engine({40, 30});
    ASSERT_NE(engine, nullptr);
    const Halves halves{.top = {255, 51, 0, 255}, .bottom = {0, 102, 204, 255}};
    engine->world().resource<Halves>() = halves;
    engine->capture_next_frame();
    ASSERT_TRUE(engine->frame(1.0 / 60).ok());
    const assets::Image captured = engine->take_captured();
    ASSERT_EQ(captured.width, 40);
    ASSERT_EQ(captured.height, 30);
    ASSERT_EQ(captured.format, assets::PixelFormat::RGBA8);
    EXPECT_EQ(pixels_not(captured, 0, 15, halves.top), 0) << "image rows 0..14 are the top of the screen";
    EXPECT_EQ(pixels_not(captured, 15, 30, halves.bottom), 0);
}

TEST(FrameSystems, NothingIsReadBackUnlessAsked) {
    auto engine = halves_engine({32, 16});
    ASSERT_NE(engine, nullptr);
    Halves& halves = engine->world().resource<Halves>();
    halves = {.top = {255, 0, 0, 255}, .bottom = {0, 0, 255, 255}};
    ASSERT_TRUE(engine->frame(1.0 / 60).ok());
    EXPECT_TRUE(engine->captured().empty()) << "no capture was asked for";

    engine->capture_next_frame();
    ASSERT_TRUE(engine->frame(1.0 / 60).ok());
    EXPECT_FALSE(engine->world().resource<systems::FrameCapture>().requested) << "a request is for one frame";
    ASSERT_EQ(engine->captured().height, 16);
    EXPECT_EQ(pixel(engine->captured(), 0, 0), (Rgba8{255, 0, 0, 255}));

    // A different frame, not asked for: the capture keeps the frame it was asked for.
    halves = {.top = {0, 255, 0, 255}, .bottom = {255, 255, 255, 255}};
    ASSERT_TRUE(engine->frame(1.0 / 60).ok());
    EXPECT_EQ(pixel(engine->captured(), 0, 0), (Rgba8{255, 0, 0, 255}));
    EXPECT_EQ(pixel(engine->captured(), 0, 15), (Rgba8{0, 0, 255, 255}));
    // ...while the display holds the new one.
    const assets::Image now = engine->read_frame();
    EXPECT_EQ(pixel(now, 0, 0), (Rgba8{0, 255, 0, 255}));
    EXPECT_EQ(pixel(now, 0, 15), (Rgba8{255, 255, 255, 255}));
}

TEST(FrameSystems, ACapturedFrameIsTheFrameReadBack) {
    auto engine =
        Engine::create(params::Params{}, {.backend = platform::BackendKind::Headless, .size = {48, 32}}, {},
                       {systems::add_puddle_plugin});
    ASSERT_TRUE(engine.ok()) << engine.error().message;
    Engine& e = **engine;
    e.capture_next_frame();
    ASSERT_TRUE(e.frame(1.0 / 60).ok());
    const assets::Image captured = e.take_captured();
    ASSERT_EQ(captured.width, 48);
    ASSERT_EQ(captured.height, 32);
    EXPECT_EQ(captured.data, e.read_frame().data)
        << "headless keeps the frame: the capture is the same pixels";
    EXPECT_GT(test::luma_stddev(captured, 0, 0, 48, 32), 1.0) << "the puddle, not an empty target";
}

// A display whose presents return results given in advance: a lost screen, then a working one.
class ScriptedDisplay final : public platform::Display {
public:
    std::deque<Result<void>> presents;
    void make_current() override {}
    platform::BackendKind kind() const override { return platform::BackendKind::Headless; }
    glm::ivec2 size() const override { return {1, 1}; }
    gpu::FrameTarget frame_target() const override { return {}; }
    bool poll_events() override { return true; }
    Result<void> present() override {
        Result<void> r = std::move(presents.front());
        presents.pop_front();
        return r;
    }
    Result<std::unique_ptr<gpu::WorkerContext>> create_worker_context() override {
        return Error{"scripted: no worker context"};
    }
    std::string describe() const override { return "scripted"; }
};

TEST(FrameSystems, PresentStatusHoldsTheLastPresentsResult) {
    ScriptedDisplay display;
    display.presents.push_back(Error{"kms: /dev/dri/card0: page flip: No such device", ExitCode::Display});
    display.presents.push_back(Result<void>{});
    systems::PresentStatus status;
    systems::OutputPower power;
    systems::present_system(display, power, status);
    ASSERT_FALSE(status.result.ok());
    EXPECT_EQ(status.result.error().message, "kms: /dev/dri/card0: page flip: No such device");
    EXPECT_EQ(status.result.error().code, ExitCode::Display);
    systems::present_system(display, power, status);
    EXPECT_TRUE(status.result.ok()) << "a later present that works replaces the error";
    EXPECT_TRUE(display.presents.empty()) << "one present per run";
}

// While the output is off: the black frame of going off is presented once, then nothing, and the status
// stays good (the watchdog is pinged on it).
TEST(FrameSystems, WhileOffOnlyTheBlackFrameIsPresentedAndTheStatusStaysGood) {
    ScriptedDisplay display;
    display.presents.push_back(Result<void>{});
    display.presents.push_back(Error{"scripted: presented while off", ExitCode::Display});
    systems::PresentStatus status{Error{"an old failure", ExitCode::Display}};
    systems::OutputPower power{.on = false, .black_frame_pending = true};
    systems::present_system(display, power, status);
    EXPECT_TRUE(status.result.ok());
    EXPECT_FALSE(power.black_frame_pending);
    EXPECT_EQ(display.presents.size(), 1u) << "the black frame was presented";
    for (int i = 0; i < 3; ++i) {
        systems::present_system(display, power, status);
        EXPECT_TRUE(status.result.ok()) << "nothing presented, nothing failed";
    }
    EXPECT_EQ(display.presents.size(), 1u) << "no present while off";
}

}  // namespace
}  // namespace puddle::app
