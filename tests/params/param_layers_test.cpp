// Precedence of the layers, clamping of knob values, presets.
#include "params/param_layers.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "params/param_docs.hpp"

namespace puddle::params {
namespace {

Config config(const char* text) {
    auto c = parse_config(text, "test.toml");
    EXPECT_TRUE(c) << c.error().message;
    return c ? *c : Config{};
}

ParamLayers layers(std::vector<ConfigEntry> command_line = {}) {
    return ParamLayers(Presets::load({}), std::move(command_line));
}

TEST(ParamLayers, PrecedenceDefaultPresetConfigKnobCommandLine) {
    auto set = parse_assignment("rain.speed=7");
    ASSERT_TRUE(set);
    ParamLayers l = layers({*set});
    // downpour sets drop_count 100, intensity 0.2, speed 2.5, fog 0.02.
    ASSERT_TRUE(l.set_config(
        config("preset = \"downpour\"\n[rain]\nintensity = 0.6\nspeed = 3.0\n[look]\nfog_density = 0.05\n")));
    l.set_knob(ParamId::look_fog_density, 0.1f);
    const Params p = l.compose();
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), 100);
    EXPECT_EQ(p.source(ParamId::rain_drop_count), ParamSource::Preset);
    EXPECT_FLOAT_EQ(p.get<ParamId::rain_intensity>(), 0.6f);  // config over preset
    EXPECT_EQ(p.source(ParamId::rain_intensity), ParamSource::Config);
    EXPECT_FLOAT_EQ(p.get<ParamId::look_fog_density>(), 0.1f);  // knob over config
    EXPECT_EQ(p.source(ParamId::look_fog_density), ParamSource::Knob);
    EXPECT_FLOAT_EQ(p.get<ParamId::rain_speed>(), 7.0f);  // --set over everything
    EXPECT_EQ(p.source(ParamId::rain_speed), ParamSource::CommandLine);
    EXPECT_EQ(p.source(ParamId::wave_resolution), ParamSource::Default);
}

TEST(ParamLayers, ARemovedConfigLineFallsBackToThePresetThenTheDefault) {
    ParamLayers l = layers();
    ASSERT_TRUE(l.set_config(config("preset = \"downpour\"\n[rain]\ndrop_count = 3\n")));
    EXPECT_EQ(l.compose().get<ParamId::rain_drop_count>(), 3);
    ASSERT_TRUE(l.set_config(config("preset = \"downpour\"\n")));
    EXPECT_EQ(l.compose().get<ParamId::rain_drop_count>(), 100);
    ASSERT_TRUE(l.set_config(config("")));
    EXPECT_EQ(l.compose().get<ParamId::rain_drop_count>(), 16);
}

TEST(ParamLayers, UnknownPresetIsRejectedWithFileLineAndTheChoices) {
    ParamLayers l = layers();
    ASSERT_TRUE(l.set_config(config("[rain]\ndrop_count = 3\n")));
    auto r = l.set_config(config("\n\npreset = \"donwpour\"\n"));
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("test.toml:3"), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find("downpour"), std::string::npos)
        << "lists the presets: " << r.error().message;
    EXPECT_EQ(l.compose().get<ParamId::rain_drop_count>(), 3) << "the last good config stays";
}

TEST(ParamLayers, KnobValuesAreClampedToTheRegisteredRange) {
    ParamLayers l = layers();
    l.set_knob(ParamId::rain_intensity, 99.0f);
    l.set_knob(ParamId::rain_drop_count, -5);
    const Params p = l.compose();
    EXPECT_FLOAT_EQ(p.get<ParamId::rain_intensity>(), static_cast<float>(decl(ParamId::rain_intensity).max));
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), static_cast<int>(decl(ParamId::rain_drop_count).min));
}

TEST(ParamLayers, AKnobPresetWinsOverTheConfigsAndClearingItGoesBack) {
    ParamLayers l = layers();
    ASSERT_TRUE(l.set_config(config("preset = \"downpour\"\n")));
    ASSERT_TRUE(l.select_preset("drizzle"));
    EXPECT_EQ(l.preset_name(), "drizzle");
    EXPECT_EQ(l.compose().get<ParamId::rain_drop_count>(), 5);
    ASSERT_TRUE(l.set_config(config("preset = \"mirror\"\n")));  // a reload keeps the knob's choice
    EXPECT_EQ(l.preset_name(), "drizzle");
    ASSERT_TRUE(l.select_preset(""));
    EXPECT_EQ(l.preset_name(), "mirror");
}

TEST(ParamLayers, StateTextRoundTripsThroughTheConfigParser) {
    ParamLayers l = layers();
    l.set_knob(ParamId::rain_intensity, 0.55f);
    l.set_knob(ParamId::ground_checkerboard, false);
    l.set_knob(ParamId::water_tint, glm::vec3(0.1f, 0.2f, 0.3f));
    ASSERT_TRUE(l.select_preset("mirror"));
    auto state = parse_config(l.state_text(), "state.toml");
    ASSERT_TRUE(state) << state.error().message << "\n" << l.state_text();
    ParamLayers restored = layers();
    ASSERT_TRUE(restored.restore_state(*state));
    const Params a = l.compose(), b = restored.compose();
    for (const ParamDecl& d : param_decls()) EXPECT_EQ(a.at(d.id), b.at(d.id)) << d.name;
    EXPECT_EQ(restored.preset_name(), "mirror");
}

// Saved state is the user's data: a knob's value comes back bit for bit, not rounded to 6 digits.
TEST(ParamLayers, SavedFloatsComeBackBitForBit) {
    ParamLayers l = layers();
    const float intensity = 1.0f / 3.0f;  // 0.333333343...: 6 significant digits would lose it
    const glm::vec3 tint(0.1234567f, 2.0f / 7.0f, 0.9999999f);
    l.set_knob(ParamId::rain_intensity, intensity);
    l.set_knob(ParamId::water_tint, tint);
    auto state = parse_config(l.state_text(), "state.toml");
    ASSERT_TRUE(state) << state.error().message << "\n" << l.state_text();
    ParamLayers restored = layers();
    ASSERT_TRUE(restored.restore_state(*state));
    EXPECT_EQ(std::get<float>(restored.compose().at(ParamId::rain_intensity)), intensity) << l.state_text();
    EXPECT_EQ(std::get<glm::vec3>(restored.compose().at(ParamId::water_tint)), tint) << l.state_text();
}

TEST(ParamLayers, PrintConfigNamesThePresetOfEachPresetValue) {
    ParamLayers l = layers();
    ASSERT_TRUE(l.set_config(config("preset = \"murky_pond\"\n")));
    const std::string text = format_effective(l.compose(), l.preset_name());
    EXPECT_NE(text.find("water.turbidity            = 0.08                     # preset murky_pond"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("rain.seed                  = 1                        # default"), std::string::npos)
        << text;
}

TEST(Presets, AtLeastFiveDocumentedLooksThatAllLoad) {
    const Presets p = Presets::load({});
    ASSERT_GE(p.names().size(), 5u);
    for (const char* name : {"drizzle", "downpour", "still_night", "murky_pond", "mirror"})
        EXPECT_TRUE(p.contains(name)) << name;
    for (const std::string& name : p.names()) {
        auto c = p.get(name);
        ASSERT_TRUE(c) << c.error().message;
        EXPECT_FALSE(c->entries.empty()) << name;
    }
    for (const EmbeddedPreset& e : embedded_presets())
        EXPECT_EQ(std::string_view(e.text).substr(0, 2), "# ")
            << e.name << " starts with a comment saying what it is";
}

TEST(Presets, StepWrapsInNameOrder) {
    const Presets p = Presets::load({});
    const auto& n = p.names();
    EXPECT_EQ(p.step(n.front(), -1), n.back());
    EXPECT_EQ(p.step(n.back(), 1), n.front());
    EXPECT_EQ(p.step(n[0], 1), n[1]);
    EXPECT_EQ(p.step("", 1), n.front());
}

TEST(ConfigKnobs, ParsesTheThreeKindsWithDefaults) {
    const Config c = config(R"(
[[knob]]
kind = "encoder"
chip = "pinctrl-bcm2711"
a = 17
b = "GPIO18"
param = "rain.intensity"
acceleration = 1.5
bias = "pull-up"
active_low = true

[[knob]]
kind = "button"
line = 27
action = "toggle"
param = "ground.checkerboard"

[[knob]]
kind = "switch"
line = 22
param = "ground.checkerboard"
debounce_ms = 50
)");
    ASSERT_EQ(c.knobs.size(), 3u);
    EXPECT_EQ(c.knobs[0].chip, "pinctrl-bcm2711");
    EXPECT_EQ(c.knobs[0].line, "17");
    EXPECT_EQ(c.knobs[0].line_b, "GPIO18");
    EXPECT_NEAR(c.knobs[0].step, 4.0 / 50, 1e-9) << "default step: 1/50 of the range";
    EXPECT_EQ(c.knobs[0].bias, LineBias::PullUp);
    EXPECT_TRUE(c.knobs[0].active_low);
    EXPECT_EQ(c.knobs[1].action, ButtonAction::Toggle);
    EXPECT_EQ(c.knobs[1].chip, "gpiochip0");
    EXPECT_EQ(c.knobs[2].debounce_ms, 50);
}

TEST(ConfigKnobs, MistakesNameFileLineAndWhatIsExpected) {
    struct Case {
        const char* text;
        const char* expect;
    };
    const Case cases[] = {
        {"[[knob]]\nkind = \"dial\"\n", "kind must be"},
        {"[[knob]]\nkind = \"encoder\"\na = 1\nparam = \"rain.intensity\"\n", "'b' is missing"},
        {"[[knob]]\nkind = \"encoder\"\na = 1\nb = 2\nparam = \"rain.intensty\"\n",
         "did you mean 'rain.intensity'"},
        {"[[knob]]\nkind = \"encoder\"\na = 1\nb = 2\nparam = \"ground.checkerboard\"\n",
         "a number parameter"},
        {"[[knob]]\nkind = \"switch\"\nline = 3\nparam = \"rain.intensity\"\n", "true/false parameter"},
        {"[[knob]]\nkind = \"button\"\nline = 3\n", "needs an action"},
        {"[[knob]]\nkind = \"button\"\nline = 3\naction = \"save\"\nspin = 2\n", "unknown key 'spin'"},
        {"[[knob]]\nkind = \"button\"\nline = -3\naction = \"save\"\n", "line must be"},
    };
    for (const Case& c : cases) {
        auto r = parse_config(c.text, "k.toml");
        ASSERT_FALSE(r) << c.text;
        EXPECT_NE(r.error().message.find("k.toml:"), std::string::npos) << r.error().message;
        EXPECT_NE(r.error().message.find(c.expect), std::string::npos) << r.error().message;
    }
}

// Issue 15, fault 3: a knob's numbers are checked as written, before anything narrows them.
TEST(ConfigKnobs, NumbersAreCheckedBeforeTheyAreStored) {
    const std::string encoder = "[[knob]]\nkind = \"encoder\"\na = 1\nb = 2\n";
    const std::string button = "[[knob]]\nkind = \"button\"\naction = \"save\"\n";
    struct Case {
        std::string text;
        const char* message;
    };
    const Case cases[] = {
        {button + "line = 3\ndebounce_ms = 20.5\n",  // was 20
         "config: k.toml:5: knob 1: debounce_ms = 20.5 is not allowed: a whole number from 0 to 1000"},
        {button + "line = 3\ndebounce_ms = 4294967316\n",
         "config: k.toml:5: knob 1: debounce_ms = 4294967316 is not allowed: a whole number from 0 to 1000"},
        {encoder + "param = \"rain.drop_count\"\nstep = 0.5\n",  // was 1
         "config: k.toml:6: knob 1: step = 0.5 is not a whole number, and rain.drop_count is an integer"},
        {encoder + "param = \"rain.intensity\"\nstep = 40\n",
         "config: k.toml:6: knob 1: step = 40 is larger than the whole range of rain.intensity (0 to 4)"},
        {button + "line = \"99999999999\"\n",  // std::stoi threw when the line was requested
         "config: k.toml:4: knob 1: line must be a line offset (0 to 4095) or a line name (at most 64 "
         "bytes)"},
    };
    for (const Case& c : cases) {
        auto r = parse_config(c.text, "k.toml");
        ASSERT_FALSE(r) << c.text;
        EXPECT_EQ(r.error().message, c.message);
    }
    auto named = parse_config(button + "line = \"17\"\n", "k.toml");
    ASSERT_TRUE(named) << named.error().message;
    EXPECT_EQ(named->knobs[0].line, "17");
}

TEST(ConfigKnobs, AtMostSixtyFourKnobs) {
    std::string text;
    for (int i = 0; i < 65; ++i)
        text += fmt::format("[[knob]]\nkind = \"button\"\naction = \"save\"\nline = {}\n", i);
    auto r = parse_config(text, "k.toml");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "config: k.toml:1: 65 [[knob]] tables; the limit is 64");
}

}  // namespace
}  // namespace puddle::params
