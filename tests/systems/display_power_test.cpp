// Tests for systems/display/display_power.hpp on a real headless engine drawing the puddle: display.power off
// shows one black frame, then runs no pass and presents nothing while the loop sleeps (CPU measured), with
// the present status good for the watchdog; the simulation clock keeps time, so the picture comes back at the
// current time; CEC messages go out through a fake adapter, and a TV that does not answer is a warning.
#include "systems/display/display_power.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <thread>

#include "app/engine.hpp"
#include "support/fake_cec_adapter.hpp"
#include "support/log_lines.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/puddle/puddle_plugin.hpp"

namespace puddle::app {
namespace {

using params::ParamId;
using params::ParamSource;

std::unique_ptr<Engine> puddle_engine() {
    platform::DisplayOptions display;
    display.backend = platform::BackendKind::Headless;
    display.size = {160, 90};
    auto engine = Engine::create(params::Params{}, display, {},
                                 {systems::add_display_power, systems::add_puddle_plugin});
    if (!engine.ok()) ADD_FAILURE() << engine.error().message;
    return engine.ok() ? std::move(*engine) : nullptr;
}

// The largest colour channel of a captured frame.
int brightest(const assets::Image& image) {
    int out = 0;
    for (std::size_t i = 0; i < image.data.size(); ++i)
        if (i % 4 != 3) out = std::max(out, static_cast<int>(image.data[i]));
    return out;
}

assets::Image captured_frame(Engine& e, double dt) {
    e.capture_next_frame();
    EXPECT_TRUE(e.frame(dt).ok());
    return e.take_captured();
}

double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);  // every thread of the process: Mesa's llvmpipe workers too
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

TEST(DisplayPower, OffShowsOneBlackFrameThenSleepsWithoutPassesAndOnComesBackAtTheCurrentTime) {
    auto engine = puddle_engine();
    ASSERT_TRUE(engine);
    Engine& e = *engine;
    const double dt = 1.0 / 60;
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(e.frame(dt).ok());
    ASSERT_GT(brightest(captured_frame(e, dt)), 20) << "the puddle is drawn while on";

    ASSERT_TRUE(e.params().set<ParamId::display_power>(false, ParamSource::Knob));
    EXPECT_EQ(brightest(captured_frame(e, dt)), 0) << "headless has no output to switch: one black frame";
    const auto& power = e.world().resource<systems::OutputPower>();
    EXPECT_FALSE(power.on);
    const auto& clock = e.world().resource<systems::FrameClock>();
    const double off_at = clock.sim_time;

    // About a second of frames while off: each sleeps systems::off_frame_sleep_seconds, so about ten of them.
    const double cpu_before = cpu_seconds();
    const auto wall_before = std::chrono::steady_clock::now();
    int frames = 0;
    while (std::chrono::steady_clock::now() - wall_before < std::chrono::seconds(1)) {
        ASSERT_TRUE(e.frame(dt).ok()) << "the present status stays good, so the watchdog is pinged";
        EXPECT_EQ(clock.steps_due, 0) << "no simulation step (a GPU pass) runs while off";
        ++frames;
    }
    const double cpu_used = cpu_seconds() - cpu_before;
    EXPECT_LE(frames, 11) << "each frame sleeps " << systems::off_frame_sleep_seconds << " s while off";
    // Bound: 5% of one core over the second (0.05 s); drawing the puddle at 60 frames a second on llvmpipe
    // takes far more than that.
    EXPECT_LT(cpu_used, 0.05) << frames << " frames took " << cpu_used << " s of CPU";
    // The clock kept time: one frame time per frame, though no step ran.
    EXPECT_NEAR(clock.sim_time - off_at, (frames + 1) * dt, clock.step_seconds + 1e-9);

    ASSERT_TRUE(e.params().set<ParamId::display_power>(true, ParamSource::Knob));
    EXPECT_GT(brightest(captured_frame(e, dt)), 20) << "the picture is back";
    EXPECT_TRUE(power.on);
}

TEST(DisplayPower, CecSendsStandbyGoingOffAndWakesTheTvComingOnAndANoAnswerIsAWarning) {
    auto engine = puddle_engine();
    ASSERT_TRUE(engine);
    Engine& e = *engine;
    test::FakeCecAdapter tv;
    auto& state = e.world().resource<systems::DisplayPower>();
    state.cec_io = &tv;
    ASSERT_TRUE(e.params().set<ParamId::display_cec>(true, ParamSource::Config));
    auto wait_for_cec = [&] {
        while (state.cec->running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    };
    test::LogLines warnings(spdlog::level::warn);
    ASSERT_TRUE(e.params().set<ParamId::display_power>(false, ParamSource::Knob));
    ASSERT_TRUE(e.frame(1.0 / 60).ok());
    wait_for_cec();
    ASSERT_EQ(tv.sent.size(), 1u);
    EXPECT_EQ(tv.sent[0], (std::vector<std::uint8_t>{0x40, CEC_MSG_STANDBY}));  // Playback 1 to the TV

    tv.tv_answers = false;
    ASSERT_TRUE(e.params().set<ParamId::display_power>(true, ParamSource::Knob));
    ASSERT_TRUE(e.frame(1.0 / 60).ok());
    wait_for_cec();
    ASSERT_EQ(tv.sent.size(), 3u);
    EXPECT_EQ(tv.sent[1], (std::vector<std::uint8_t>{0x40, CEC_MSG_IMAGE_VIEW_ON}));
    EXPECT_EQ(tv.sent[2], (std::vector<std::uint8_t>{0x4f, CEC_MSG_ACTIVE_SOURCE, 0x10, 0x00}));
    ASSERT_TRUE(e.frame(1.0 / 60).ok());  // the outcome is logged by the next frame
    EXPECT_EQ(
        warnings.count("cec: /dev/cec0: <Image View On> and <Active Source> sent, the TV did not answer"), 1);
    EXPECT_EQ(tv.open_fds, 0);
}

}  // namespace
}  // namespace puddle::app
