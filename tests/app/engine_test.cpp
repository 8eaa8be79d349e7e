// Tests for src/app/engine.hpp: the frame is one run of the schedule, whose order is pinned here; the
// engine knows no feature by name; the exit stage runs once.
#include "app/engine.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/app.hpp"
#include "ecs/frame_time.hpp"
#include "support/puddle_schedule.hpp"
#include "support/test_support.hpp"
#include "systems/puddle/puddle_plugin.hpp"

namespace puddle::app {
namespace {

platform::DisplayOptions headless(glm::ivec2 size = {64, 36}) {
    platform::DisplayOptions display;
    display.backend = platform::BackendKind::Headless;
    display.size = size;
    return display;
}

// The schedule of the puddle binary, system by system: the frame from the clock to the present. A change
// of order, of a run condition or of what a system reads and writes shows here first; update it on purpose.
std::vector<std::string> binary_schedule() {
    std::vector<std::string> lines = {
        "input/begin frame (reads Params, AdaptiveScale; writes Display, Device, OutputCanvas, RenderTarget)",
        "input/gpu timer begin if output on (writes AdaptiveScale)",
        "input/reload signal (writes ReloadSignal, TuningInbox)",
        "input/schedule (reads WallClock, LiveTuning; writes ZoneCheck, ScheduleRun, TuningInbox)",
        "input/live tuning (writes TuningInbox, LiveTuning, Params)",
        "input/display power (reads Params; writes Display, Device, OutputPower, DisplayPower)",
        "input/synced changes if wall.clock is realtime (reads WallClock, FrameClock, OutputPower; writes "
        "LiveTuning, Params, WallSteps)",
    };
    lines.insert(lines.end(), test::puddle_plugin_schedule.begin(), test::puddle_plugin_schedule.end());
    for (const char* line :
         {"present/output canvas if output on (reads OutputCanvas; writes Device)",
          "present/adaptive scale if output on (reads Params; writes Device, AdaptiveScale)",
          "present/capture (writes Display, Device, FrameCapture)",
          "present/present (writes Display, OutputPower, PresentStatus)",
          "present/watchdog ping (reads PresentStatus; writes ServiceNotify)",
          "present/sleep while off (reads OutputPower)", "exit/service stopping (writes ServiceNotify)",
          "exit/save state (writes LiveTuning)"})
        lines.emplace_back(line);
    return lines;
}

TEST(Engine, TheBinarysFrameIsThisScheduleInThisOrder) {
    auto signals = std::make_unique<StopSignals>();
    systems::ServiceNotify service;
    systems::LiveTuning tuning(params::ParamLayers({}, {}));
    auto engine = Engine::create(params::Params{}, headless(), {}, puddle_features(signals, service, tuning));
    ASSERT_TRUE(engine.ok()) << engine.error().message;
    const std::vector<std::string> lines = (*engine)->schedule().describe();
    EXPECT_EQ(lines, binary_schedule());
    if (lines != binary_schedule())
        for (const std::string& line : lines) ADD_FAILURE() << line;
}

struct Counts {
    int frames = 0;
    int exits = 0;
};
void count_frame(Counts& c) {
    ++c.frames;
}
void count_exit(Counts& c) {
    ++c.exits;
}

TEST(Engine, WithoutFeaturesItRunsOnlyTheDisplaysSystemsAndPresents) {
    Counts* counts = nullptr;
    auto engine = Engine::create(params::Params{}, headless(), {},
                                 {[&](ecs::World& w, ecs::Schedule& s) -> Result<void> {
                                     counts = &w.insert_resource<Counts>();
                                     s.add(ecs::Stage::Render, "count", count_frame);
                                     s.add(ecs::Stage::Exit, "count exit", count_exit);
                                     return {};
                                 }});
    ASSERT_TRUE(engine.ok()) << engine.error().message;
    Engine& e = **engine;
    EXPECT_EQ(e.schedule().describe(),
              (std::vector<std::string>{
                  "input/begin frame (reads Params, AdaptiveScale; writes Display, Device, OutputCanvas, "
                  "RenderTarget)",
                  "input/gpu timer begin if output on (writes AdaptiveScale)",
                  "render/count (writes Counts)",
                  "present/output canvas if output on (reads OutputCanvas; writes Device)",
                  "present/adaptive scale if output on (reads Params; writes Device, AdaptiveScale)",
                  "present/capture (writes Display, Device, FrameCapture)",
                  "present/present (writes Display, OutputPower, PresentStatus)",
                  "exit/count exit (writes Counts)",
              }));
    ASSERT_TRUE(e.frame(1.0 / 60).ok());
    ASSERT_TRUE(e.frame(1.0 / 60).ok());
    EXPECT_EQ(counts->frames, 2);
    EXPECT_DOUBLE_EQ(e.world().resource<ecs::FrameTime>().dt_seconds, 1.0 / 60);
    EXPECT_EQ(counts->exits, 0);
    e.shutdown();
    e.shutdown();
    EXPECT_EQ(counts->exits, 1) << "the exit stage runs once";
}

TEST(Engine, APluginErrorStopsCreationWithItsMessage) {
    auto engine =
        Engine::create(params::Params{}, headless(), {}, {[](ecs::World&, ecs::Schedule&) -> Result<void> {
                           return Error{"sky: cannot open /x.hdr", ExitCode::Asset};
                       }});
    ASSERT_FALSE(engine.ok());
    EXPECT_EQ(engine.error().code, ExitCode::Asset);
    EXPECT_EQ(engine.error().message, "sky: cannot open /x.hdr");
}

TEST(Engine, DebugLoggingPrintsTheScheduleOnceAtStartUp) {
    const test::CommandResult r = test::run_puddle("-b headless --size 32x18 --frames 3 --log-level debug");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::size_t lines = 0;
    for (std::size_t at = r.output.find("schedule: "); at != std::string::npos;
         at = r.output.find("schedule: ", at + 1))
        ++lines;
    EXPECT_EQ(lines, binary_schedule().size()) << r.output;
    EXPECT_NE(r.output.find("schedule: " + binary_schedule().front()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("schedule: " + binary_schedule().back()), std::string::npos) << r.output;
    // At info level, not at all.
    const test::CommandResult quiet = test::run_puddle("-b headless --size 32x18 --frames 1");
    EXPECT_EQ(quiet.output.find("schedule: "), std::string::npos) << quiet.output;
}

}  // namespace
}  // namespace puddle::app
