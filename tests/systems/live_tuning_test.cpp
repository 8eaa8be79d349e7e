// The live-tuning system: config reloads and knob turns reaching Params, the delayed state save.
#include "systems/tuning/live_tuning.hpp"

#include <gtest/gtest.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>

#include "io/gpio_mock.hpp"
#include "support/log_lines.hpp"
#include "support/test_support.hpp"

namespace puddle::systems {
namespace {

using params::ParamId;
using params::ParamSource;

struct Rig {
    test::TempDir dir;
    std::string config_path;
    io::MockGpio* gpio = nullptr;
    TuningInbox inbox;
    std::optional<LiveTuning> tuning;
    params::Params params;

    // watch_config false: as if inotify were unavailable (edits then apply on SIGHUP only).
    explicit Rig(const std::string& config_text, bool watch_config = true) {
        config_path = dir.write("puddle.toml", config_text);
        tuning.emplace(params::ParamLayers(params::Presets::load({}), {}));
        tuning->config_path = config_path;
        auto config = params::load_config_file(config_path);
        EXPECT_TRUE(config) << config.error().message;
        EXPECT_TRUE(tuning->layers.set_config(std::move(*config)));
        auto mock = std::make_unique<io::MockGpio>();
        gpio = mock.get();
        tuning->gpio = std::move(mock);
        tuning->state.emplace((dir / "state.toml").string());
        params = tuning->layers.compose();
        if (!watch_config) tuning->config_path.clear();
        start_live_tuning(*tuning);
        tuning->config_path = config_path;
    }
    void step(double now) { live_tuning_step(inbox, *tuning, params, now); }
    void write_config(const std::string& text) {
        const std::string temp = dir.write("puddle.toml.new", text);
        std::filesystem::rename(temp, config_path);  // as editors save
    }
};

TEST(LiveTuning, AnEditedConfigAppliesOnTheNextFrame) {
    Rig rig("[rain]\ndrop_count = 10\n");
    rig.step(1.0);
    const auto revision = rig.params.revision();
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 10);
    rig.write_config("[rain]\ndrop_count = 30\n[look]\nvignette = 1.0\n");
    rig.step(1.016);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 30);
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::look_vignette>(), 1.0f);
    EXPECT_GT(rig.params.revision(), revision);
}

TEST(LiveTuning, AnInvalidFileKeepsTheLastGoodConfigAndTheNextValidSaveApplies) {
    Rig rig("[rain]\ndrop_count = 10\n");
    rig.step(1.0);
    rig.write_config("[rain]\ndrop_count = 10\nintensity = 99\n");  // out of range: nothing applies
    rig.step(1.1);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 10);
    rig.write_config("[rain\ngarbage");
    rig.step(1.2);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 10);
    rig.write_config("[rain]\ndrop_count = 12\n");
    rig.step(1.3);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 12);
}

// Issue 15, fault 2: a live edit to a 50 000-level dotted key killed the running display (SIGSEGV).
TEST(LiveTuning, AConfigPastTheInputLimitsKeepsTheLastGoodConfig) {
    Rig rig("[rain]\ndrop_count = 10\n");
    rig.step(1.0);
    std::string deep = "a";
    for (int i = 0; i < 50000; ++i) deep += ".a";
    rig.write_config("[rain]\ndrop_count = 30\n" + deep + " = 1\n");
    rig.step(1.1);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 10);
    rig.write_config("[" + deep + "]\n");
    rig.step(1.2);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 10);
    rig.write_config("[rain]\ndrop_count = 12\n");
    rig.step(1.3);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 12);
}

TEST(LiveTuning, DeletedConfigKeepsRunningAndARecreatedOneApplies) {
    Rig rig("[rain]\ndrop_count = 10\n");
    rig.step(1.0);
    std::filesystem::remove(rig.config_path);
    rig.step(1.1);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 10);
    std::ofstream(rig.config_path) << "[rain]\ndrop_count = 20\n";
    rig.step(1.2);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 20);
}

// Every source but the knobs asks through the inbox; live tuning acts on the requests in the order asked,
// in its next step, and empties it. A flood past the inbox's capacity is counted and said once.
TEST(LiveTuning, TheInboxIsActedOnInOrderAndAFloodIsCounted) {
    Rig rig("[rain]\ndrop_count = 10\n");
    rig.step(1.0);
    rig.inbox.push(SetRemoteValue{.id = ParamId::rain_drop_count, .value = 20});
    rig.inbox.push(SetRemoteValue{.id = ParamId::rain_drop_count, .value = 30});
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 10) << "nothing applies before the step";
    rig.step(1.1);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 30);
    EXPECT_EQ(rig.params.source(ParamId::rain_drop_count), params::ParamSource::Remote);
    EXPECT_TRUE(rig.inbox.requests.empty());
    EXPECT_TRUE(rig.tuning->state_unsaved()) << "a remote value is saved with the knob state";

    for (std::size_t i = 0; i < TuningInbox::capacity + 5; ++i)
        rig.inbox.push(SetRemoteValue{.id = ParamId::rain_drop_count, .value = 40});
    EXPECT_EQ(rig.inbox.requests.size(), TuningInbox::capacity);
    EXPECT_EQ(rig.inbox.dropped, 5u);
    rig.step(1.2);
    EXPECT_EQ(rig.inbox.dropped, 0u) << "said once, then counted afresh";
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 40);

    rig.inbox.push(SelectPreset{.name = "no-such-preset"});  // the sender checks; a late failure is a warning
    rig.step(1.3);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 40);
}

TEST(LiveTuning, SighupReloads) {
    Rig rig("[rain]\ndrop_count = 10\n", false);
    std::ofstream(rig.config_path) << "[rain]\ndrop_count = 11\n";
    rig.step(1.0);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 10);
    rig.inbox.push(ReloadConfig{});
    rig.step(1.1);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 11);
}

TEST(LiveTuning, AnUnchangedReloadDoesNotBumpTheRevision) {
    Rig rig("[rain]\ndrop_count = 10\n");
    rig.step(1.0);
    const auto revision = rig.params.revision();
    rig.write_config("[rain]\ndrop_count = 10\n");
    rig.step(1.1);
    EXPECT_EQ(rig.params.revision(), revision) << "no rebuilds for a save without changes";
}

constexpr const char* knob_config = R"(
[rain]
intensity = 0.5

[[knob]]
kind = "encoder"
a = 17
b = 18
param = "rain.intensity"
step = 0.1

[[knob]]
kind = "button"
line = 27
action = "next-preset"
)";

void turn(io::MockGpio& gpio, double t, int detents) {
    for (int i = 0; i < detents; ++i, t += 0.5) {
        gpio.set_level("gpiochip0", 17, false, t);
        gpio.set_level("gpiochip0", 18, false, t + 0.001);
        gpio.set_level("gpiochip0", 17, true, t + 0.002);
        gpio.set_level("gpiochip0", 18, true, t + 0.003);
    }
}

TEST(LiveTuning, KnobTurnsChangeTheParameterClampedAndSaveTheStateAfterADelay) {
    Rig rig(knob_config);
    rig.gpio->set_level("gpiochip0", 17, true, 0);
    rig.gpio->set_level("gpiochip0", 18, true, 0);
    rig.step(1.0);  // opens the lines
    turn(*rig.gpio, 1.1, 2);
    rig.step(2.5);
    EXPECT_NEAR(rig.params.get<ParamId::rain_intensity>(), 0.7f, 1e-5);
    EXPECT_EQ(rig.params.source(ParamId::rain_intensity), ParamSource::Knob);
    EXPECT_FALSE(std::filesystem::exists(rig.dir / "state.toml"))
        << "saved a few seconds after the last change";
    rig.step(2.5 + LiveTuning::save_delay_seconds);
    finish_state_save(*rig.tuning);  // written on the saver thread
    ASSERT_TRUE(std::filesystem::exists(rig.dir / "state.toml"));
    auto saved = params::load_config_file((rig.dir / "state.toml").string());
    ASSERT_TRUE(saved);
    ASSERT_EQ(saved->entries.size(), 1u);
    EXPECT_NEAR(std::get<float>(saved->entries[0].value), 0.7f, 1e-5);

    for (int i = 0; i < 3; ++i) {  // far past the top of the range
        turn(*rig.gpio, 10.0 + 20.0 * i, 20);
        rig.step(20.0 + 20.0 * i);
    }
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::rain_intensity>(), 4.0f);
}

// The log lines at warning level and above while it lives.
struct Warnings : test::LogLines {
    Warnings() : LogLines(spdlog::level::warn) {}
};

// A save that fails the same way at every knob turn (a folder in the state's place, a refusal, a full
// disk) is one line, not one per save; after a save that works, a new failure is reported again.
TEST(LiveTuning, ASaveThatKeepsFailingIsReportedOnce) {
    Rig rig(knob_config);
    const Warnings warnings;
    const std::string failure =
        "state: cannot replace " + (rig.dir / "state.toml").string() + ": Is a directory";
    std::filesystem::create_directories(rig.dir / "state.toml");
    rig.gpio->set_level("gpiochip0", 17, true, 0);
    rig.gpio->set_level("gpiochip0", 18, true, 0);
    rig.step(1.0);
    for (int i = 0; i < 3; ++i) {
        turn(*rig.gpio, 2.0 + 10.0 * i, 1);
        rig.step(3.0 + 10.0 * i);
        rig.step(3.0 + 10.0 * i + LiveTuning::save_delay_seconds);  // the save, which fails
        finish_state_save(*rig.tuning);
    }
    EXPECT_EQ(warnings.count(failure), 1);

    std::filesystem::remove(rig.dir / "state.toml");
    turn(*rig.gpio, 40.0, 1);
    rig.step(41.0);
    rig.step(41.0 + LiveTuning::save_delay_seconds);
    finish_state_save(*rig.tuning);
    ASSERT_TRUE(std::filesystem::is_regular_file(rig.dir / "state.toml"));

    std::filesystem::remove(rig.dir / "state.toml");
    std::filesystem::create_directories(rig.dir / "state.toml");
    turn(*rig.gpio, 50.0, 1);
    rig.step(51.0);
    rig.step(51.0 + LiveTuning::save_delay_seconds);
    finish_state_save(*rig.tuning);
    EXPECT_EQ(warnings.count(failure), 2);
}

// A knob value whose save failed (a folder in the state's place; a full disk alike) is tried again a delay
// later without another turn, and at exit: it used to be forgotten until the next turn, so a value turned
// once and followed by a restart was lost.
TEST(LiveTuning, AFailedSaveIsTriedAgainUntilItIsWritten) {
    Rig rig(knob_config);
    std::filesystem::create_directories(rig.dir / "state.toml");
    rig.gpio->set_level("gpiochip0", 17, true, 0);
    rig.gpio->set_level("gpiochip0", 18, true, 0);
    rig.step(1.0);
    turn(*rig.gpio, 1.1, 1);
    rig.step(2.0);
    rig.step(2.0 + LiveTuning::save_delay_seconds);  // fails: a folder
    finish_state_save(*rig.tuning);
    std::filesystem::remove(rig.dir / "state.toml");
    rig.step(3.0 + LiveTuning::save_delay_seconds);  // too soon to retry
    finish_state_save(*rig.tuning);
    EXPECT_FALSE(std::filesystem::exists(rig.dir / "state.toml"));
    rig.step(6.0 + LiveTuning::save_delay_seconds);  // retried with no new turn
    finish_state_save(*rig.tuning);
    auto saved = params::load_config_file((rig.dir / "state.toml").string());
    ASSERT_TRUE(saved) << saved.error().message;
    ASSERT_EQ(saved->entries.size(), 1u);
    EXPECT_NEAR(std::get<float>(saved->entries[0].value), 0.6f, 1e-5);

    // At exit: a failed save is written by the exit stage once the way is clear.
    std::filesystem::remove(rig.dir / "state.toml");
    std::filesystem::create_directories(rig.dir / "state.toml");
    turn(*rig.gpio, 20.0, 1);
    rig.step(21.0);
    rig.step(21.0 + LiveTuning::save_delay_seconds);
    finish_state_save(*rig.tuning);
    std::filesystem::remove(rig.dir / "state.toml");
    save_state(*rig.tuning);
    saved = params::load_config_file((rig.dir / "state.toml").string());
    ASSERT_TRUE(saved) << saved.error().message;
    EXPECT_NEAR(std::get<float>(saved->entries[0].value), 0.7f, 1e-5);
}

// A save stuck on the disk (an SD card taking seconds to flush, played here by a FIFO in the place of the
// temporary file, whose open waits for a reader) holds no frame: the steps go on, the knob keeps working,
// and the save finishes once the disk answers. Before, the frame thread wrote the file itself and waited.
TEST(LiveTuning, ASlowDiskNeverHoldsAFrame) {
    Rig rig(knob_config);
    const std::filesystem::path temp = rig.dir / "state.toml.tmp";
    ASSERT_EQ(::mkfifo(temp.c_str(), 0600), 0);
    rig.gpio->set_level("gpiochip0", 17, true, 0);
    rig.gpio->set_level("gpiochip0", 18, true, 0);
    rig.step(1.0);
    turn(*rig.gpio, 1.1, 1);
    // The steps run on their own thread, so that a step stuck on the FIFO fails the test instead of
    // hanging it: the reader below is opened (unblocking the writer) whether or not the steps returned.
    auto frames = std::async(std::launch::async, [&] {
        rig.step(2.0);
        rig.step(2.0 + LiveTuning::save_delay_seconds);  // starts the save, which blocks in open()
        turn(*rig.gpio, 10.0, 1);
        rig.step(10.5);
    });
    const bool frames_went_on = frames.wait_for(std::chrono::seconds(20)) == std::future_status::ready;
    {
        std::ifstream reader(temp);  // the disk answers
        std::string ignored((std::istreambuf_iterator<char>(reader)), {});
    }
    frames.wait();
    EXPECT_TRUE(frames_went_on) << "a frame waited for the state file";
    EXPECT_NEAR(rig.params.get<ParamId::rain_intensity>(), 0.7f, 1e-5) << "the knob kept working meanwhile";
    finish_state_save(*rig.tuning);
    std::filesystem::remove(temp);
    save_state(*rig.tuning);  // the exit stage writes the value turned while the disk was stuck
    auto saved = params::load_config_file((rig.dir / "state.toml").string());
    ASSERT_TRUE(saved) << saved.error().message;
    ASSERT_EQ(saved->entries.size(), 1u);
    EXPECT_NEAR(std::get<float>(saved->entries[0].value), 0.7f, 1e-5);
}

TEST(LiveTuning, AConfigReloadDoesNotUndoAKnob) {
    Rig rig(knob_config);
    rig.gpio->set_level("gpiochip0", 17, true, 0);
    rig.gpio->set_level("gpiochip0", 18, true, 0);
    rig.step(1.0);
    turn(*rig.gpio, 1.1, 1);
    rig.step(2.0);
    EXPECT_NEAR(rig.params.get<ParamId::rain_intensity>(), 0.6f, 1e-5);
    std::string text = knob_config;
    text.replace(text.find("0.5"), 3, "0.2");
    rig.write_config(text + "\n[look]\nvignette = 0.9\n");
    rig.step(2.1);
    EXPECT_NEAR(rig.params.get<ParamId::rain_intensity>(), 0.6f, 1e-5) << "knob state is above the config";
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::look_vignette>(), 0.9f);
}

// A preset file beside the config is the user's to edit too: a reload (SIGHUP, or an edited config)
// reads the presets again. They were read once at start, so an edited preset needed a restart.
TEST(LiveTuning, AReloadReadsAnEditedPresetAgain) {
    Rig rig("[rain]\nintensity = 0.5\n");
    std::filesystem::create_directories(rig.dir / "presets");
    rig.dir.write("presets/mine.toml", "[rain]\ndrop_count = 5\n");
    rig.tuning->preset_folders = {(rig.dir / "presets").string()};
    rig.write_config("preset = \"mine\"\n");
    rig.inbox.push(ReloadConfig{});  // as SIGHUP does
    rig.step(1.0);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 5);
    rig.dir.write("presets/mine.toml", "[rain]\ndrop_count = 6\n");
    rig.inbox.push(ReloadConfig{});
    rig.step(2.0);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 6);
    // A preset edited into something invalid keeps the last good one running, presets and config alike.
    rig.dir.write("presets/mine.toml", "[rain]\ndrop_count = 999\n");
    rig.inbox.push(ReloadConfig{});
    rig.step(3.0);
    EXPECT_EQ(rig.params.get<ParamId::rain_drop_count>(), 6);
    EXPECT_EQ(rig.tuning->layers.preset_name(), "mine");
}

TEST(LiveTuning, AButtonStepsThroughThePresets) {
    Rig rig(knob_config);
    rig.step(1.0);
    rig.gpio->set_level("gpiochip0", 27, true, 1.5);
    rig.step(1.6);
    const std::string first = rig.tuning->layers.preset_name();
    EXPECT_EQ(first, rig.tuning->layers.presets().names().front());
    rig.gpio->set_level("gpiochip0", 27, false, 2.0);
    rig.gpio->set_level("gpiochip0", 27, true, 2.5);
    rig.step(2.6);
    EXPECT_EQ(rig.tuning->layers.preset_name(), rig.tuning->layers.presets().names()[1]);
}

}  // namespace
}  // namespace puddle::systems
