// Knobs on the mock GPIO backend: the same Knob code that runs on libgpiod.
#include "io/knob.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>

#include "io/gpio_mock.hpp"
#include "support/log_lines.hpp"
#include "support/test_support.hpp"

namespace puddle::io {
namespace {

using params::KnobKind;
using params::KnobSpec;
using params::ParamId;

KnobSpec encoder(double step = 0.05, double acceleration = 0) {
    KnobSpec k;
    k.kind = KnobKind::Encoder;
    k.line = "17";
    k.line_b = "18";
    k.param = ParamId::rain_intensity;
    k.step = step;
    k.acceleration = acceleration;
    return k;
}

KnobSpec button(params::ButtonAction action) {
    KnobSpec k;
    k.kind = KnobKind::Button;
    k.line = "27";
    k.action = action;
    k.active_low = true;
    k.bias = params::LineBias::PullUp;
    return k;
}

// One clockwise detent (A leads) from rest 11, edges 1 ms apart starting at t.
void turn_clockwise(MockGpio& gpio, double t) {
    gpio.set_level("gpiochip0", 17, false, t);
    gpio.set_level("gpiochip0", 18, false, t + 0.001);
    gpio.set_level("gpiochip0", 17, true, t + 0.002);
    gpio.set_level("gpiochip0", 18, true, t + 0.003);
}
void turn_counter_clockwise(MockGpio& gpio, double t) {
    gpio.set_level("gpiochip0", 18, false, t);
    gpio.set_level("gpiochip0", 17, false, t + 0.001);
    gpio.set_level("gpiochip0", 18, true, t + 0.002);
    gpio.set_level("gpiochip0", 17, true, t + 0.003);
}

struct Rig {
    MockGpio gpio;
    std::vector<KnobAction> actions;
    GoneChips gone;
    Rig() {
        actions.reserve(64);
        gpio.set_level("gpiochip0", 17, true, 0);
        gpio.set_level("gpiochip0", 18, true, 0);
    }
};

TEST(Knob, EncoderTurnsGiveSignedSteps) {
    Rig rig;
    Knob knob(encoder(0.05));
    knob.update(rig.gpio, 1.0, rig.actions, rig.gone);
    ASSERT_TRUE(knob.open());
    turn_clockwise(rig.gpio, 2.0);
    turn_clockwise(rig.gpio, 3.0);
    turn_counter_clockwise(rig.gpio, 4.0);
    knob.update(rig.gpio, 4.1, rig.actions, rig.gone);
    ASSERT_EQ(rig.actions.size(), 3u);
    EXPECT_DOUBLE_EQ(rig.actions[0].amount, 0.05);
    EXPECT_DOUBLE_EQ(rig.actions[1].amount, 0.05);
    EXPECT_DOUBLE_EQ(rig.actions[2].amount, -0.05);
}

TEST(Knob, AccelerationGrowsTheStepForFastTurnsOnly) {
    Rig rig;
    Knob knob(encoder(0.05, 1.0));
    knob.update(rig.gpio, 1.0, rig.actions, rig.gone);
    turn_clockwise(rig.gpio, 2.0);                                          // slow: a second after nothing
    turn_clockwise(rig.gpio, 3.0);                                          // 1 detent/s: no gain
    for (int i = 0; i < 4; ++i) turn_clockwise(rig.gpio, 3.05 + 0.05 * i);  // 20 detents/s
    knob.update(rig.gpio, 4.0, rig.actions, rig.gone);
    ASSERT_EQ(rig.actions.size(), 6u);
    EXPECT_DOUBLE_EQ(rig.actions[1].amount, 0.05);
    EXPECT_NEAR(rig.actions[5].amount, 0.05 * (1 + (20 - 2) / 6.0), 1e-6);
}

TEST(Knob, ButtonPressIsDebouncedAndReportedOnce) {
    Rig rig;
    Knob knob(button(params::ButtonAction::NextPreset));
    knob.update(rig.gpio, 1.0, rig.actions, rig.gone);
    ASSERT_TRUE(knob.open());
    EXPECT_TRUE(rig.actions.empty()) << "pull-up, active low: released at rest";
    // Press with bounce, then hold.
    rig.gpio.set_level("gpiochip0", 27, false, 2.000);
    rig.gpio.set_level("gpiochip0", 27, true, 2.002);
    rig.gpio.set_level("gpiochip0", 27, false, 2.004);
    knob.update(rig.gpio, 2.010, rig.actions, rig.gone);
    EXPECT_TRUE(rig.actions.empty()) << "not yet held for 20 ms";
    knob.update(rig.gpio, 2.030, rig.actions, rig.gone);
    ASSERT_EQ(rig.actions.size(), 1u);
    EXPECT_EQ(rig.actions[0].kind, KnobAction::Kind::Press);
    // Release with bounce: no second press.
    rig.gpio.set_level("gpiochip0", 27, true, 3.000);
    rig.gpio.set_level("gpiochip0", 27, false, 3.001);
    rig.gpio.set_level("gpiochip0", 27, true, 3.002);
    knob.update(rig.gpio, 3.1, rig.actions, rig.gone);
    EXPECT_EQ(rig.actions.size(), 1u);
}

TEST(Knob, SwitchReportsItsPositionAtOnceAndOnChange) {
    Rig rig;
    KnobSpec k;
    k.kind = KnobKind::Switch;
    k.line = "22";
    k.param = ParamId::ground_checkerboard;
    rig.gpio.set_level("gpiochip0", 22, true, 0);
    Knob knob(k);
    knob.update(rig.gpio, 1.0, rig.actions, rig.gone);
    ASSERT_EQ(rig.actions.size(), 1u);
    EXPECT_TRUE(rig.actions[0].level);
    rig.gpio.set_level("gpiochip0", 22, false, 2.0);
    knob.update(rig.gpio, 2.5, rig.actions, rig.gone);
    ASSERT_EQ(rig.actions.size(), 2u);
    EXPECT_EQ(rig.actions[1].kind, KnobAction::Kind::Level);
    EXPECT_FALSE(rig.actions[1].level);
}

TEST(Knob, MissingChipWarnsAndStartsWorkingWhenItAppears) {
    Rig rig;
    KnobSpec k = encoder();
    k.chip = "gpiochip1";
    Knob knob(k);
    knob.update(rig.gpio, 1.0, rig.actions, rig.gone);
    EXPECT_FALSE(knob.open());
    rig.gpio.add_chip("gpiochip1", "usb-expander");
    rig.gpio.set_level("gpiochip1", 17, true, 1.5);
    rig.gpio.set_level("gpiochip1", 18, true, 1.5);
    knob.update(rig.gpio, 2.0, rig.actions, rig.gone);
    EXPECT_FALSE(knob.open()) << "retries only every few seconds";
    knob.update(rig.gpio, 1.0 + Knob::retry_seconds, rig.actions, rig.gone);
    EXPECT_TRUE(knob.open());
}

TEST(Knob, UnpluggedChipClosesTheKnobAndReplugReopensIt) {
    Rig rig;
    Knob knob(encoder());
    knob.update(rig.gpio, 1.0, rig.actions, rig.gone);
    ASSERT_TRUE(knob.open());
    rig.gpio.remove_chip("gpiochip0");
    knob.update(rig.gpio, 2.0, rig.actions, rig.gone);
    EXPECT_FALSE(knob.open());
    rig.gpio.add_chip("gpiochip0");
    knob.update(rig.gpio, 2.0 + Knob::retry_seconds, rig.actions, rig.gone);
    EXPECT_TRUE(knob.open());
}

TEST(Knob, UnplugIsOneWarningAndTheRetriesWhileGoneAreQuiet) {
    // On a real chip (gpio-sim's live=0 in the VM test) the lines fail first, then every retry finds no
    // chip: one problem, one warning; coming back is one info line.
    Rig rig;
    Knob knob(encoder());
    knob.update(rig.gpio, 1.0, rig.actions, rig.gone);
    ASSERT_TRUE(knob.open());
    test::LogLines warnings(spdlog::level::warn);
    test::LogLines infos(spdlog::level::info);
    rig.gpio.remove_chip("gpiochip0");
    for (int i = 0; i < 4; ++i) knob.update(rig.gpio, 2.0 + i * Knob::retry_seconds, rig.actions, rig.gone);
    EXPECT_FALSE(knob.open());
    EXPECT_EQ(warnings.count("gpio"), 1);
    rig.gpio.add_chip("gpiochip0");
    knob.update(rig.gpio, 2.0 + 5 * Knob::retry_seconds, rig.actions, rig.gone);
    EXPECT_TRUE(knob.open());
    EXPECT_EQ(infos.count("works now"), 1);
    rig.gpio.remove_chip("gpiochip0");  // a second unplug warns again
    knob.update(rig.gpio, 30.0, rig.actions, rig.gone);
    knob.update(rig.gpio, 30.0 + Knob::retry_seconds, rig.actions, rig.gone);
    EXPECT_EQ(warnings.count("gpio"), 2);
}

TEST(Knob, KnobsOnOneUnpluggedChipShareOneWarning) {
    // The VM test's wiring: an encoder, a button and a switch on one chip, which goes away (live=0).
    Rig rig;
    std::vector<Knob> knobs;
    knobs.emplace_back(encoder());
    knobs.emplace_back(button(params::ButtonAction::NextPreset));
    KnobSpec other_chip = button(params::ButtonAction::NextPreset);
    other_chip.chip = "gpiochip1";
    other_chip.line = "4";
    rig.gpio.add_chip("gpiochip1");
    rig.gpio.set_level("gpiochip1", 4, true, 0);
    knobs.emplace_back(other_chip);
    for (Knob& k : knobs) k.update(rig.gpio, 1.0, rig.actions, rig.gone);
    for (const Knob& k : knobs) ASSERT_TRUE(k.open()) << k.spec().describe();

    test::LogLines warnings(spdlog::level::warn);
    test::LogLines infos(spdlog::level::info);
    rig.gpio.remove_chip("gpiochip0");
    for (int i = 0; i < 4; ++i)
        for (Knob& k : knobs) k.update(rig.gpio, 2.0 + i * Knob::retry_seconds, rig.actions, rig.gone);
    EXPECT_FALSE(knobs[0].open());
    EXPECT_FALSE(knobs[1].open());
    EXPECT_TRUE(knobs[2].open()) << "a knob on another chip goes on";
    ASSERT_EQ(warnings.count("gpio"), 1);
    EXPECT_EQ(warnings.count("chip gpiochip0 and every knob on it"), 1);

    rig.gpio.add_chip("gpiochip0");
    for (Knob& k : knobs) k.update(rig.gpio, 2.0 + 5 * Knob::retry_seconds, rig.actions, rig.gone);
    EXPECT_TRUE(knobs[0].open());
    EXPECT_TRUE(knobs[1].open());
    EXPECT_EQ(infos.count("works now"), 2);

    rig.gpio.remove_chip("gpiochip0");  // a second unplug warns again, once
    for (int i = 0; i < 3; ++i)
        for (Knob& k : knobs) k.update(rig.gpio, 30.0 + i * Knob::retry_seconds, rig.actions, rig.gone);
    EXPECT_EQ(warnings.count("gpio"), 2);
}

}  // namespace
}  // namespace puddle::io
