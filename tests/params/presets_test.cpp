// Presets (params/presets.hpp): the built-in looks, stepping through them, and preset folders that add a
// look or replace a built-in one; what get() says of a missing preset or one that holds more than values.
#include "params/presets.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace puddle::params {
namespace {

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

// The default ground is the paving; the reference's checkerboard look is one preset away.
TEST(Presets, ReferenceBringsBackTheCheckerboard) {
    EXPECT_FALSE(std::get<bool>(decl(ParamId::ground_checkerboard).default_value));
    const Presets p = Presets::load({});
    auto c = p.get("reference");
    ASSERT_TRUE(c) << c.error().message;
    bool checkerboard = false;
    for (const ConfigEntry& e : c->entries)
        if (e.id == ParamId::ground_checkerboard) checkerboard = std::get<bool>(e.value);
    EXPECT_TRUE(checkerboard);
}

TEST(Presets, StepWrapsInNameOrder) {
    const Presets p = Presets::load({});
    const auto& n = p.names();
    EXPECT_EQ(p.step(n.front(), -1), n.back());
    EXPECT_EQ(p.step(n.back(), 1), n.front());
    EXPECT_EQ(p.step(n[0], 1), n[1]);
    EXPECT_EQ(p.step("", 1), n.front());
}

// Fails if a folder's file were added beside the built-in of the same name instead of replacing it, or if
// files other than .toml were read.
TEST(Presets, AFolderAddsALookAndReplacesABuiltInOfTheSameName) {
    test::TempDir dir;
    dir.write("downpour.toml", "# mine\n[rain]\ndrop_count = 7\n");
    dir.write("fog.toml", "# new\n[look]\nfog_density = 0.2\n");
    dir.write("notes.txt", "[rain]\ndrop_count = 9\n");
    const std::vector<std::string> folders{dir.path().string(), (dir / "absent").string()};
    const Presets p = Presets::load(folders);
    const Presets builtin = Presets::load({});
    EXPECT_EQ(p.names().size(), builtin.names().size() + 1) << "fog added, downpour replaced, notes ignored";
    EXPECT_TRUE(p.contains("fog"));
    EXPECT_FALSE(p.contains("notes"));
    auto downpour = p.get("downpour");
    ASSERT_TRUE(downpour) << downpour.error().message;
    ASSERT_EQ(downpour->entries.size(), 1u);
    EXPECT_EQ(downpour->entries[0].id, ParamId::rain_drop_count);
    EXPECT_EQ(std::get<int>(downpour->entries[0].value), 7);
}

TEST(Presets, GetNamesAMissingPresetAndRefusesOneWithMoreThanValues) {
    test::TempDir dir;
    dir.write("nested.toml", "preset = \"downpour\"\n");
    const std::vector<std::string> folders{dir.path().string()};
    const Presets p = Presets::load(folders);
    auto missing = p.get("nope");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ExitCode::Config);
    EXPECT_TRUE(missing.error().message.starts_with("preset 'nope' does not exist (presets: "))
        << missing.error().message;
    for (const std::string& name : p.names())
        EXPECT_NE(missing.error().message.find(name), std::string::npos) << name;
    auto nested = p.get("nested");
    ASSERT_FALSE(nested);
    EXPECT_EQ(nested.error().message, "config: " + (dir / "nested.toml").string() +
                                          ": a preset holds parameters only (no preset = or [[knob]])");
}

}  // namespace
}  // namespace puddle::params
