// Tests for systems/tuning/synced_changes.hpp: with the realtime clock, a config edit that two screens of a
// wall read at different moments is applied by both at the same step, the step of the next change boundary.
#include "systems/tuning/synced_changes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>

#include "schedule/tz_guard.hpp"
#include "support/test_support.hpp"
#include "systems/tuning/schedule_system.hpp"

namespace puddle::systems {
namespace {

using params::ParamId;

constexpr std::int64_t start_ns = 1'764'590'400LL * ns_per_second + 400'000'000;  // 12:00:00.4 UTC
constexpr std::int64_t frame_ns = 16'666'667;

const char* const config_before = "[wall]\nclock = \"realtime\"\n[rain]\nintensity = 0.3\n";
const char* const config_after = "[wall]\nclock = \"realtime\"\n[rain]\nintensity = 0.8\n";

// One screen of a wall: its own config file, live tuning, and the frame's input and simulate stages.
struct Screen {
    explicit Screen(std::int64_t phase_ns, const char* config_text = config_before)
        : now(start_ns + phase_ns) {
        config_path = dir.write("puddle.toml", config_text);
        tuning.emplace(params::ParamLayers(params::Presets::load({}), {}));
        tuning->config_path = config_path;
        auto config = params::load_config_file(config_path);
        EXPECT_TRUE(config) << config.error().message;
        EXPECT_TRUE(tuning->layers.set_config(std::move(*config)));
        params = tuning->layers.compose();
        start_live_tuning(*tuning);
        wall.now_ns = [this] { return now; };
    }
    // One frame: the input stage's systems in the binary's order, then the due steps, each noting the
    // intensity it simulated with.
    void frame() {
        schedule_step(schedule, *tuning, inbox, static_cast<double>(now) * 1e-9);
        live_tuning_step(inbox, *tuning, params, static_cast<double>(now) * 1e-9);
        synced_changes_system(wall, clock, power, *tuning, params, steps);
        wall_steps_system(wall, power, look, params, steps, clock);
        for (int i = 0; i < clock.steps_due; ++i) {
            begin_step_system(clock);
            if (!first_new_step && params.get<ParamId::rain_intensity>() == 0.8f)
                first_new_step = clock.step_index;
        }
        now += frame_ns;
    }
    void edit_config() {
        const std::string temp = dir.write("puddle.toml.new", config_after);
        std::filesystem::rename(temp, config_path);  // as an editor or a deploy tool saves
    }

    test::TempDir dir;
    std::string config_path;
    TuningInbox inbox;
    ScheduleRun schedule;
    std::optional<LiveTuning> tuning;
    params::Params params;
    std::int64_t now;
    WallClock wall;
    OutputPower power;
    ShownLook look;
    WallSteps steps;
    FrameClock clock;
    std::optional<std::uint64_t> first_new_step;
};

TEST(SyncedChanges, AConfigEditReadAtDifferentMomentsAppliesAtTheSameStep) {
    Screen a(0), b(7'000'000);                          // b's frames start 7 ms into a's
    for (int i = 0; i < 30; ++i) a.frame(), b.frame();  // both joined and in step
    ASSERT_EQ(a.params.get<ParamId::wall_clock>(), params::WallClockMode::realtime);
    a.edit_config();
    const std::int64_t read_at = a.now;
    for (int i = 0; i < 3; ++i) a.frame(), b.frame();  // the edit reaches b's copy 50 ms later
    b.edit_config();
    for (int i = 0; i < 240; ++i) a.frame(), b.frame();
    ASSERT_TRUE(a.first_new_step && b.first_new_step);
    EXPECT_EQ(*a.first_new_step, *b.first_new_step);
    // The step of the next whole second after the read, plus one second.
    EXPECT_EQ(static_cast<std::int64_t>(*a.first_new_step), step_at(change_boundary(read_at, 1.0), 60.0));
    EXPECT_EQ(a.steps.change_step, 0u);
    EXPECT_FALSE(pending_change(*a.tuning));
}

// A schedule's transition is a wall time, which each screen passes in its own frame: it applies at the
// wall's change step like any change, so the screens switch at the same step.
TEST(SyncedChanges, AScheduleTransitionAppliesAtTheSameStepOnEveryScreen) {
    test::TzGuard tz("UTC");
    const char* const scheduled =
        "[wall]\nclock = \"realtime\"\n[[schedule]]\nfrom = \"12:01\"\nto = \"13:00\"\n"
        "set = { \"rain.intensity\" = 0.8 }\n";
    Screen a(0, scheduled), b(7'000'000, scheduled);
    for (int i = 0; i < 30; ++i) a.frame(), b.frame();
    ASSERT_EQ(a.params.get<ParamId::rain_intensity>(), 0.3f) << "12:00: the entry is not in force yet";
    const std::int64_t transition = start_ns - 400'000'000 + 60 * ns_per_second;  // 12:01:00 UTC
    while (a.now < transition + 3 * ns_per_second) a.frame(), b.frame();
    ASSERT_TRUE(a.first_new_step && b.first_new_step);
    EXPECT_EQ(*a.first_new_step, *b.first_new_step);
    // Read in the frame that passed 12:01:00: the step of the next whole second after it, plus one second.
    EXPECT_EQ(static_cast<std::int64_t>(*a.first_new_step), step_at(change_boundary(transition, 1.0), 60.0));
}

// While the output is off nothing is simulated, yet a pending change still applies at its time. Held for a
// step that never came, it never applied: a reload setting display.power = true left the screen dark.
TEST(SyncedChanges, AChangeWhileTheOutputIsOffAppliesAtItsTime) {
    Screen a(0);
    for (int i = 0; i < 30; ++i) a.frame();
    a.power.on = false;
    const std::int64_t at = a.now + 300'000'000;
    a.inbox.push(SetRemoteValue{.id = ParamId::rain_intensity, .value = 0.8f, .apply_at_ns = at});
    for (int i = 0; i < 30; ++i) a.frame();
    EXPECT_EQ(a.params.get<ParamId::rain_intensity>(), 0.8f);
    EXPECT_FALSE(pending_change(*a.tuning));
    EXPECT_GE(a.now, at);
}

// A remote message's apply_at is the step, wherever in the period it was read.
TEST(SyncedChanges, ARemoteApplyAtIsTheStep) {
    Screen a(0);
    for (int i = 0; i < 30; ++i) a.frame();
    const std::int64_t at = a.now + 500'000'000;
    a.inbox.push(SetRemoteValue{.id = ParamId::rain_intensity, .value = 0.8f, .apply_at_ns = at});
    for (int i = 0; i < 60; ++i) a.frame();
    ASSERT_TRUE(a.first_new_step);
    EXPECT_EQ(static_cast<std::int64_t>(*a.first_new_step), step_at(at, 60.0));
}

// An apply_at far ahead (a typo: the year 2255) or already past lands at the next boundary: held for it,
// this change and every later one would wait for centuries.
TEST(SyncedChanges, AnApplyAtPastOrMoreThanAnHourAheadLandsAtTheBoundary) {
    for (const std::int64_t offset : {-5 * ns_per_second, max_apply_ahead_ns + ns_per_second,
                                      std::int64_t{9'000'000'000} * ns_per_second - start_ns}) {
        SCOPED_TRACE(offset);
        Screen a(0);
        for (int i = 0; i < 30; ++i) a.frame();
        a.inbox.push(
            SetRemoteValue{.id = ParamId::rain_intensity, .value = 0.8f, .apply_at_ns = a.now + offset});
        const std::int64_t read_at = a.now;
        for (int i = 0; i < 180; ++i) a.frame();
        ASSERT_TRUE(a.first_new_step);
        EXPECT_EQ(static_cast<std::int64_t>(*a.first_new_step), step_at(change_boundary(read_at, 1.0), 60.0));
        EXPECT_FALSE(pending_change(*a.tuning)) << "nothing left pending";
    }
}

}  // namespace
}  // namespace puddle::systems
