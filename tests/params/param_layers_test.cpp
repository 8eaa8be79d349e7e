// Precedence of the layers, clamping of knob values, presets.
#include "params/param_layers.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "params/param_docs.hpp"
#include "support/parsed_config.hpp"

namespace puddle::params {
namespace {

Config config(const char* text) {
    return test::parsed_config(text);
}

ParamLayers layers(std::vector<ConfigEntry> command_line = {}) {
    return ParamLayers(Presets::load({}), std::move(command_line));
}

TEST(ParamLayers, PrecedenceDefaultPresetConfigKnobCommandLine) {
    auto set = parse_assignment("rain.speed=7");
    ASSERT_TRUE(set);
    ParamLayers l = layers({*set});
    // downpour sets rate 14, drift 0.3, intensity 0.25, fog 0.02.
    ASSERT_TRUE(l.set_config(
        config("preset = \"downpour\"\n[rain]\nintensity = 0.6\nspeed = 3.0\n[look]\nfog_density = 0.05\n")));
    l.set_knob(ParamId::look_fog_density, 0.1f);
    const Params p = l.compose();
    EXPECT_FLOAT_EQ(p.get<ParamId::rain_rate>(), 14.0f);
    EXPECT_EQ(p.source(ParamId::rain_rate), ParamSource::Preset);
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
    ASSERT_TRUE(l.set_config(config("preset = \"downpour\"\n[rain]\nrate = 3.5\n")));
    EXPECT_FLOAT_EQ(l.compose().get<ParamId::rain_rate>(), 3.5f);
    ASSERT_TRUE(l.set_config(config("preset = \"downpour\"\n")));
    EXPECT_FLOAT_EQ(l.compose().get<ParamId::rain_rate>(), 14.0f);
    ASSERT_TRUE(l.set_config(config("")));
    EXPECT_FLOAT_EQ(l.compose().get<ParamId::rain_rate>(), 3.0f);
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
    EXPECT_FLOAT_EQ(l.compose().get<ParamId::rain_rate>(), 0.4f);
    ASSERT_TRUE(l.set_config(config("preset = \"mirror\"\n")));  // a reload keeps the knob's choice
    EXPECT_EQ(l.preset_name(), "drizzle");
    ASSERT_TRUE(l.select_preset(""));
    EXPECT_EQ(l.preset_name(), "mirror");
}

// --preset NAME (a new user's first try was --set preset=downpour): instead of the config's `preset =`,
// with or without a config, at every reload; a knob's choice still wins; an unknown name lists the choices.
TEST(ParamLayers, ACommandLinePresetReplacesTheConfigsAndAKnobStillWins) {
    ParamLayers l = layers();
    ASSERT_TRUE(l.set_command_line_preset("downpour"));
    EXPECT_EQ(l.preset_name(), "downpour") << "without a config";
    EXPECT_FLOAT_EQ(l.compose().get<ParamId::rain_rate>(), 14.0f);
    EXPECT_EQ(l.compose().source(ParamId::rain_rate), ParamSource::Preset);
    ASSERT_TRUE(l.set_config(config("preset = \"mirror\"\n")));
    EXPECT_EQ(l.preset_name(), "downpour") << "over the config's";
    ASSERT_TRUE(l.set_config(config("[rain]\nintensity = 0.6\n")));  // a reload
    EXPECT_EQ(l.preset_name(), "downpour");
    EXPECT_FLOAT_EQ(l.compose().get<ParamId::rain_intensity>(), 0.6f) << "config values over the preset's";
    ASSERT_TRUE(l.select_preset("drizzle"));
    EXPECT_EQ(l.preset_name(), "drizzle");
    ASSERT_TRUE(l.select_preset(""));
    EXPECT_EQ(l.preset_name(), "downpour") << "cleared, the knob goes back to --preset's";
    const auto bad = l.set_command_line_preset("donwpour");
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().code, ExitCode::Config);
    EXPECT_NE(bad.error().message.find("--preset"), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("downpour"), std::string::npos)
        << "lists them: " << bad.error().message;
    EXPECT_EQ(l.preset_name(), "downpour") << "unchanged";
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

namespace puddle::params {
namespace {

// Remote values share the knob level (the last writer holds a parameter) and are saved in the same state
// file, marked so that a restart restores them as Remote.
TEST(ParamLayersRemote, RemoteValuesAreTheKnobLevelAndSurviveTheStateFile) {
    ParamLayers layers(Presets::load({}), {});
    layers.set_remote(ParamId::rain_intensity, 0.7f);
    layers.set_knob(ParamId::look_vignette, 1.0f);
    Params p = layers.compose();
    EXPECT_EQ(p.source(ParamId::rain_intensity), ParamSource::Remote);
    EXPECT_EQ(p.source(ParamId::look_vignette), ParamSource::Knob);
    EXPECT_EQ(source_name(ParamSource::Remote), "remote");

    const std::string text = layers.state_text();
    EXPECT_NE(text.find("remote = [\"rain.intensity\"]\n"), std::string::npos) << text;
    auto state = parse_config(text, "state.toml");
    ASSERT_TRUE(state) << state.error().message;
    ParamLayers restored(Presets::load({}), {});
    ASSERT_TRUE(restored.restore_state(*state));
    p = restored.compose();
    EXPECT_EQ(p.source(ParamId::rain_intensity), ParamSource::Remote);
    EXPECT_EQ(p.get<ParamId::rain_intensity>(), 0.7f);
    EXPECT_EQ(p.source(ParamId::look_vignette), ParamSource::Knob);

    restored.set_knob(ParamId::rain_intensity, 0.2f);  // a knob turned after the broker: the knob holds it
    EXPECT_EQ(restored.compose().source(ParamId::rain_intensity), ParamSource::Knob);
    EXPECT_EQ(restored.state_text().find("remote ="), std::string::npos);
}

TEST(ParamLayersRemote, SourcesKeepTheirOrder) {
    EXPECT_LT(ParamSource::Config, ParamSource::Schedule);
    EXPECT_LT(ParamSource::Schedule, ParamSource::Knob);
    EXPECT_LT(ParamSource::Knob, ParamSource::Remote);
    EXPECT_LT(ParamSource::Remote, ParamSource::CommandLine);
}

}  // namespace
}  // namespace puddle::params
