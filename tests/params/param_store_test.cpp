// The parameter values in force (params/param_store.hpp): every parameter starts at its default, a value
// from a higher source wins, the revision counts real changes only, and the sources' names and order.
#include "params/param_store.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace puddle::params {
namespace {

TEST(Params, StartsAtTheDefaults) {
    const Params p;
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), std::get<int>(decl(ParamId::rain_drop_count).default_value));
    EXPECT_EQ(p.get<ParamId::rain_intensity>(), std::get<float>(decl(ParamId::rain_intensity).default_value));
    EXPECT_EQ(p.get<ParamId::ground_checkerboard>(),
              std::get<bool>(decl(ParamId::ground_checkerboard).default_value));
    EXPECT_EQ(p.get<ParamId::water_tint>(), std::get<glm::vec3>(decl(ParamId::water_tint).default_value));
    EXPECT_EQ(p.get<ParamId::render_method>(), RenderMethod::intersect);
    EXPECT_EQ(p.get<ParamId::environment_image>(), "");
    for (const ParamDecl& d : param_decls()) {
        EXPECT_EQ(p.at(d.id), d.default_value) << d.name;
        EXPECT_EQ(p.source(d.id), ParamSource::Default) << d.name;
    }
}

TEST(Params, HigherSourceWinsAndRevisionCountsRealChanges) {
    Params p;
    const std::uint64_t r0 = p.revision();

    EXPECT_TRUE(p.set(ParamId::rain_drop_count, 20, ParamSource::Config));
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), 20);
    EXPECT_EQ(p.source(ParamId::rain_drop_count), ParamSource::Config);
    const std::uint64_t r1 = p.revision();
    EXPECT_GT(r1, r0);

    // Same value again: accepted, but nothing changed, so the revision stays.
    EXPECT_TRUE(p.set(ParamId::rain_drop_count, 20, ParamSource::Config));
    EXPECT_EQ(p.revision(), r1);

    // A higher source overrides.
    EXPECT_TRUE(p.set(ParamId::rain_drop_count, 40, ParamSource::CommandLine));
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), 40);
    EXPECT_EQ(p.source(ParamId::rain_drop_count), ParamSource::CommandLine);
    const std::uint64_t r2 = p.revision();
    EXPECT_GT(r2, r1);

    // Lower sources do not, and the revision does not move.
    EXPECT_FALSE(p.set(ParamId::rain_drop_count, 5, ParamSource::Config));
    EXPECT_FALSE(p.set(ParamId::rain_drop_count, 6, ParamSource::Knob));
    EXPECT_FALSE(p.set(ParamId::rain_drop_count, 7, ParamSource::Default));
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), 40);
    EXPECT_EQ(p.source(ParamId::rain_drop_count), ParamSource::CommandLine);
    EXPECT_EQ(p.revision(), r2);

    // Other parameters are independent: a config value still applies to them.
    EXPECT_TRUE(p.set(ParamId::rain_speed, 2.0f, ParamSource::Config));
    EXPECT_EQ(p.get<ParamId::rain_speed>(), 2.0f);
    EXPECT_EQ(p.revision(), r2 + 1);

    // Setting the current value from a higher source raises the source without a revision change.
    EXPECT_TRUE(p.set(ParamId::rain_speed, 2.0f, ParamSource::Knob));
    EXPECT_EQ(p.source(ParamId::rain_speed), ParamSource::Knob);
    EXPECT_EQ(p.revision(), r2 + 1);
    EXPECT_FALSE(p.set(ParamId::rain_speed, 3.0f, ParamSource::Preset));
    EXPECT_EQ(p.get<ParamId::rain_speed>(), 2.0f);
}

TEST(Params, SourceNames) {
    EXPECT_EQ(source_name(ParamSource::Default), "default");
    EXPECT_EQ(source_name(ParamSource::Preset), "preset");
    EXPECT_EQ(source_name(ParamSource::Config), "config");
    EXPECT_EQ(source_name(ParamSource::Knob), "knob");
    EXPECT_EQ(source_name(ParamSource::CommandLine), "--set");
    EXPECT_LT(ParamSource::Default, ParamSource::Preset);
    EXPECT_LT(ParamSource::Preset, ParamSource::Config);
    EXPECT_LT(ParamSource::Config, ParamSource::Knob);
    EXPECT_LT(ParamSource::Knob, ParamSource::CommandLine);
}

}  // namespace
}  // namespace puddle::params

namespace puddle::params {
namespace {

// A value that get<>() could not read back as its declared type is refused, not stored: a wrong kind, or
// an enum text that is no choice (it used to be stored, with the old choice index left behind).
TEST(ParamsSet, AWrongKindOrAnUnknownChoiceIsRefusedAndChangesNothing) {
    Params p;
    const auto revision = p.revision();
    EXPECT_FALSE(p.set(ParamId::render_method, ParamValue(std::string("fast")), ParamSource::CommandLine));
    EXPECT_FALSE(p.set(ParamId::rain_drop_count, ParamValue(2.5f), ParamSource::CommandLine));
    EXPECT_FALSE(p.set(ParamId::rain_intensity, ParamValue(3), ParamSource::CommandLine));
    EXPECT_EQ(p.get<ParamId::render_method>(), RenderMethod::intersect);
    EXPECT_EQ(std::get<std::string>(p.at(ParamId::render_method)), "intersect");
    EXPECT_EQ(p.revision(), revision);
    EXPECT_EQ(p.source(ParamId::render_method), ParamSource::Default);
}

TEST(ParamsSet, TheTypedSetStoresTheChoiceAndItsText) {
    Params p;
    EXPECT_TRUE(p.set<ParamId::render_method>(RenderMethod::raymarch, ParamSource::CommandLine));
    EXPECT_EQ(p.get<ParamId::render_method>(), RenderMethod::raymarch);
    EXPECT_EQ(std::get<std::string>(p.at(ParamId::render_method)), "raymarch");
    EXPECT_TRUE(p.set<ParamId::rain_drop_count>(7, ParamSource::CommandLine));
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), 7);
    EXPECT_FALSE(p.set<ParamId::rain_drop_count>(9, ParamSource::Config)) << "below --set";
}

}  // namespace
}  // namespace puddle::params
