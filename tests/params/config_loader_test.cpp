// Tests for src/params/config_loader.hpp: the TOML config, its error messages, --set, and the shipped
// config/puddle.toml.
#include "params/config_loader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "support/test_support.hpp"

namespace puddle::params {
namespace {

// Passes when `needle` occurs in `text`; a failure prints both.
::testing::AssertionResult has_text(const std::string& text, std::string_view needle) {
    if (text.find(needle) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "'" << needle << "' is not in:\n" << text;
}

// The error of a config that must not parse.
Error config_error(std::string_view text, std::string_view path = "file.toml") {
    auto r = parse_config(text, path);
    if (r) {
        ADD_FAILURE() << "parsed, expected an error:\n" << text;
        return {};
    }
    EXPECT_EQ(r.error().code, ExitCode::Config);
    return r.error();
}

const ConfigEntry* entry_for(const Config& c, ParamId id) {
    for (const ConfigEntry& e : c.entries)
        if (e.id == id) return &e;
    return nullptr;
}

TEST(ParseConfig, ValidFileApplies) {
    const char* text =
        "# a comment\n"
        "[rain]\n"
        "drop_count = 20\n"
        "intensity = 1.5\n"
        "speed = 2        # an integer is fine for a float\n"
        "\n"
        "[water]\n"
        "tint = [0.1, 0.2, 0.3]\n"
        "\n"
        "[ground]\n"
        "checkerboard = false\n"
        "image = \"/srv/paving.png\"\n"
        "\n"
        "[render]\n"
        "method = \"raymarch\"\n";
    auto r = parse_config(text, "file.toml");
    ASSERT_TRUE(r) << r.error().message;
    const Config& c = *r;
    EXPECT_EQ(c.path, "file.toml");
    ASSERT_EQ(c.entries.size(), 7u);
    // Each entry keeps its line number (toml++ tables are sorted by key, so the order is not the file's).
    const std::pair<ParamId, int> lines[] = {
        {ParamId::rain_drop_count, 3}, {ParamId::rain_intensity, 4},       {ParamId::rain_speed, 5},
        {ParamId::water_tint, 8},      {ParamId::ground_checkerboard, 11}, {ParamId::ground_image, 12},
        {ParamId::render_method, 15},
    };
    for (const auto& [id, line] : lines) {
        const ConfigEntry* e = entry_for(c, id);
        ASSERT_NE(e, nullptr) << decl(id).name;
        EXPECT_EQ(e->line, line) << decl(id).name;
    }

    Params p;
    const auto before = p.revision();
    apply_config(c, p);
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), 20);
    EXPECT_EQ(p.get<ParamId::rain_intensity>(), 1.5f);
    EXPECT_EQ(p.get<ParamId::rain_speed>(), 2.0f);
    EXPECT_EQ(p.get<ParamId::water_tint>(), glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_FALSE(p.get<ParamId::ground_checkerboard>());
    EXPECT_EQ(p.get<ParamId::ground_image>(), "/srv/paving.png");
    EXPECT_EQ(p.get<ParamId::render_method>(), RenderMethod::raymarch);
    EXPECT_EQ(p.source(ParamId::rain_drop_count), ParamSource::Config);
    EXPECT_EQ(p.source(ParamId::wave_damping), ParamSource::Default);  // not in the file
    EXPECT_EQ(p.at(ParamId::wave_damping), decl(ParamId::wave_damping).default_value);
    EXPECT_GT(p.revision(), before);
}

TEST(ParseConfig, EmptyFileHasNoEntries) {
    auto r = parse_config("", "empty.toml");
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_TRUE(r->entries.empty());
    auto comments = parse_config("# nothing here\n\n[rain]\n", "c.toml");
    ASSERT_TRUE(comments) << comments.error().message;
    EXPECT_TRUE(comments->entries.empty());
}

TEST(ParseConfig, ApplyDoesNotOverrideTheCommandLine) {
    auto r = parse_config("[rain]\ndrop_count = 20\nspeed = 3\n", "file.toml");
    ASSERT_TRUE(r) << r.error().message;
    Params p;
    ASSERT_TRUE(p.set(ParamId::rain_drop_count, 50, ParamSource::CommandLine));
    apply_config(*r, p);
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), 50);
    EXPECT_EQ(p.get<ParamId::rain_speed>(), 3.0f);
    // Applied as a preset (below the config), a later config wins.
    Params q;
    apply_config(*r, q, ParamSource::Preset);
    EXPECT_EQ(q.source(ParamId::rain_speed), ParamSource::Preset);
    EXPECT_TRUE(q.set(ParamId::rain_speed, 4.0f, ParamSource::Config));
}

TEST(ParseConfig, UnknownKeyNamesFileLineKeyAndSuggestion) {
    const Error e = config_error("[rain]\nintensity = 1\ndrop_cont = 20\n");
    EXPECT_TRUE(has_text(e.message, "file.toml:3"));
    EXPECT_TRUE(has_text(e.message, "rain.drop_cont"));
    EXPECT_TRUE(has_text(e.message, "did you mean 'rain.drop_count'"));
    EXPECT_EQ(e.message,
              "config: file.toml:3: unknown key 'rain.drop_cont' (did you mean 'rain.drop_count'?)");
}

// Letters outside ASCII where TOML wants a key, whitespace or '=' (toml++ 3.3 checks them against a
// whitespace table that has no case for U+00A1..U+0499 or U+2D6E..U+3167: see CMakeLists.txt's sanitizer
// flags). Each is one line naming the line and the character; in a string or a comment they are fine.
TEST(ParseConfig, NonAsciiOutsideStringsIsASyntaxErrorNamingTheCharacter) {
    EXPECT_TRUE(has_text(config_error("[rain]\nintensit\xc3\xa9 = 0.5\n").message, "file.toml:2:"));
    EXPECT_TRUE(has_text(config_error("[rain]\nintensit\xc3\xa9 = 0.5\n").message, "saw '\xc3\xa9'"));
    EXPECT_TRUE(has_text(config_error("kindt\xc6\x9b\"\nline = 22\n").message, "saw '\xc6\x9b'"));
    EXPECT_TRUE(has_text(config_error("[rain] \xe3\x80\x81\n").message, "saw '\xe3\x80\x81'"));
    EXPECT_TRUE(has_text(config_error("[rain]\nintensity = 0.5 \xce\xbb\n").message, "file.toml:2:"));
    auto ok = parse_config(
        "# pluie fine, \xc3\xa9t\xc3\xa9 \xe3\x80\x81\n[environment]\nimage = "
        "\"/srv/\xc3\xa9t\xc3\xa9.hdr\"\n",
        "file.toml");
    EXPECT_TRUE(ok) << ok.error().message;
}

TEST(ParseConfig, UnknownSectionIsAnUnknownKey) {
    const Error e = config_error("[rian]\ndrop_count = 20\n");
    EXPECT_EQ(e.message,
              "config: file.toml:2: unknown key 'rian.drop_count' (did you mean 'rain.drop_count'?)");
}

TEST(ParseConfig, OutOfRangeNamesFileLineKeyValueAndRange) {
    const Error e = config_error("[rain]\n\ndrop_count = 500\n");
    EXPECT_TRUE(has_text(e.message, "file.toml:3"));
    EXPECT_TRUE(has_text(e.message, "rain.drop_count"));
    EXPECT_TRUE(has_text(e.message, "500"));
    EXPECT_TRUE(has_text(e.message, "from 1 to 128"));
    EXPECT_EQ(
        e.message,
        "config: file.toml:3: rain.drop_count = 500 is out of range: allowed an integer from 1 to 128 drops");

    const Error f = config_error("[wave]\ndamping = 1.5\n");
    EXPECT_EQ(f.message,
              "config: file.toml:2: wave.damping = 1.5 is out of range: allowed a number from 0.9 to 1");

    const Error c = config_error("[water]\ntint = [0.1, 2.0, 0.3]\n");
    EXPECT_TRUE(has_text(c.message, "file.toml:2"));
    EXPECT_TRUE(has_text(c.message, "water.tint = [0.1, 2, 0.3] is out of range"));
    EXPECT_TRUE(has_text(c.message, "each from 0 to 1 rgb"));

    const Error m = config_error("[render]\nmethod = \"fast\"\n");
    EXPECT_EQ(m.message,
              "config: file.toml:2: render.method = \"fast\" is not allowed: one of: intersect, raymarch");
}

TEST(ParseConfig, HugeIntegerIsOutOfRangeNotWrapped) {
    const Error e = config_error("[rain]\ndrop_count = 5000000000\n");
    // The value as written, not the int it was narrowed to.
    EXPECT_EQ(e.message,
              "config: file.toml:2: rain.drop_count = 5000000000 is out of range: allowed an integer from 1 "
              "to 128 drops");
}

// Issue 15, fault 3: two screens given seeds past int's range both ran with 2147483647, the same rain.
TEST(ParseConfig, NumbersAreCheckedBeforeTheyAreNarrowed) {
    EXPECT_EQ(config_error("[rain]\nseed = 4294967297\n").message,
              "config: file.toml:2: rain.seed = 4294967297 is out of range: allowed an integer from 0 to "
              "2147483647");
    EXPECT_EQ(
        config_error("[rain]\nseed = 9223372036854775807\n").message,
        "config: file.toml:2: rain.seed = 9223372036854775807 is out of range: allowed an integer from 0 to "
        "2147483647");
    EXPECT_EQ(config_error("[rain]\nseed = -4294967295\n").message,
              "config: file.toml:2: rain.seed = -4294967295 is out of range: allowed an integer from 0 to "
              "2147483647");
    // A double past a float's range is out of range as written, not infinity.
    EXPECT_EQ(
        config_error("[rain]\nintensity = 1e300\n").message,
        "config: file.toml:2: rain.intensity = 1e+300 is out of range: allowed a number from 0 to 4 height");
    EXPECT_EQ(config_error("[camera]\nposition = [1, 1e300, 3]\n").message,
              "config: file.toml:2: camera.position = [1, 1e+300, 3] is out of range: allowed three numbers "
              "[x, y, z], "
              "each from -1000 to 1000 units");
    // An integer too large for a float parameter is out of range, not a wrong type.
    EXPECT_EQ(config_error("[rain]\nintensity = 9223372036854775807\n").message,
              "config: file.toml:2: rain.intensity = 9223372036854775807 is out of range: allowed a number "
              "from 0 to 4 "
              "height");
    // The largest seed still fits.
    auto ok = parse_config("[rain]\nseed = 2147483647\n", "file.toml");
    ASSERT_TRUE(ok) << ok.error().message;
    EXPECT_EQ(std::get<int>(ok->entries[0].value), 2147483647);
}

// toml++ refuses numbers past 64 bits or past a double itself, in words that named neither the key nor
// the range ("Error while parsing floating-point: '1e400' could not be interpreted as a value").
TEST(ParseConfig, NumbersTooBigForTomlAreOutOfRangeWithKeyAndRange) {
    EXPECT_EQ(
        config_error("[rain]\nintensity = 1e400 # very wet\n").message,
        "config: file.toml:2: rain.intensity = 1e400 is out of range: allowed a number from 0 to 4 height");
    EXPECT_EQ(
        config_error("[rain]\nseed = 9223372036854775808\n").message,
        "config: file.toml:2: rain.seed = 9223372036854775808 is out of range: allowed an integer from 0 "
        "to 2147483647");
    EXPECT_EQ(config_error("rain.seed = -0x1ffffffffffffffff\n").message.substr(0, 47),
              "config: file.toml:1: rain.seed: Error while par");
    EXPECT_EQ(
        config_error("[rain]\n\"seed\" = 0x1ffffffffffffffff\n").message,
        "config: file.toml:2: rain.seed = 0x1ffffffffffffffff is out of range: allowed an integer from 0 "
        "to 2147483647");
    EXPECT_EQ(config_error("[camera]\nposition = [1, 1e400, 3]\n").message,
              "config: file.toml:2: camera.position = [1, 1e400, 3] is out of range: allowed three numbers "
              "[x, y, z], each from -1000 to 1000 units");
    // Another syntax error on a key's line names the key; toml++'s words keep no raw newline.
    const Error bool_typo = config_error("[ground]\ncheckerboard = tru\n");
    EXPECT_TRUE(
        bool_typo.message.starts_with("config: file.toml:2: ground.checkerboard: Error while parsing"))
        << bool_typo.message;
    EXPECT_EQ(bool_typo.message.find('\n'), std::string::npos) << bool_typo.message;
    // An unknown key with a huge number keeps toml++'s words, with the key.
    EXPECT_TRUE(
        config_error("[rain]\nwind = 1e400\n").message.starts_with("config: file.toml:2: rain.wind: "));
}

// A name typed (or pasted) at any length gives one readable line: clipped, its length said.
TEST(ParseConfig, ALongUnknownNameIsClippedInTheMessage) {
    const std::string name(200, 'w');  // keys past 256 bytes are refused by toml_limits before this
    const Error e = config_error("[rain]\n" + name + " = 1\n");
    EXPECT_LT(e.message.size(), 200u) << e.message;
    EXPECT_TRUE(has_text(e.message, "unknown key 'rain.wwww")) << e.message;
    EXPECT_TRUE(has_text(e.message, "... (205 bytes)")) << e.message;
    auto set = parse_assignment("rain." + std::string(5000, 'w') + "=1");
    ASSERT_FALSE(set);
    EXPECT_LT(set.error().message.size(), 300u) << set.error().message;
    auto value = parse_assignment("render.method=" + name);
    ASSERT_FALSE(value);
    EXPECT_LT(value.error().message.size(), 300u) << value.error().message;
}

TEST(ParseConfig, TheTwoScreensOfTheVideoWallAreRefused) {
    const std::string dir = std::string(PUDDLE_SHARED_DIR) + "/cases/config";
    if (!std::filesystem::exists(dir + "/screen1.toml"))
        GTEST_SKIP() << "needs ../shared/cases/config (absent)";
    const std::pair<const char*, const char*> screens[] = {{"screen1.toml", "4294967297"},
                                                           {"screen2.toml", "9223372036854775807"}};
    for (const auto& [file, seed] : screens) {
        auto r = load_config_file(dir + "/" + file);
        ASSERT_FALSE(r) << file << " was accepted";
        EXPECT_EQ(r.error().code, ExitCode::Config);
        EXPECT_EQ(r.error().message,
                  fmt::format("config: {}/{}:3: rain.seed = {} is out of range: allowed an "
                              "integer from 0 to 2147483647",
                              dir, file, seed));
    }
}

TEST(ParseConfigKeepingValid, KeepsEveryValidKeyAndReportsEachBadOneInFileOrder) {
    auto r = parse_config_keeping_valid(
        "[rain]\nintensity = 0.8\nwind = 0.5\nseed = 4294967297\n[look]\nvignette = 1.2\n[water]\nturbidity "
        "= 2.5\n",
        "state.toml");
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(r->config.entries.size(), 2u);
    EXPECT_EQ(r->config.entries[0].id, ParamId::rain_intensity);
    EXPECT_FLOAT_EQ(std::get<float>(r->config.entries[0].value), 0.8f);
    EXPECT_EQ(r->config.entries[1].id, ParamId::look_vignette);
    EXPECT_FLOAT_EQ(std::get<float>(r->config.entries[1].value), 1.2f);
    ASSERT_EQ(r->dropped.size(), 3u);
    EXPECT_TRUE(has_text(r->dropped[0], "config: state.toml:3: unknown key 'rain.wind' (did you mean"));
    EXPECT_EQ(r->dropped[1],
              "config: state.toml:4: rain.seed = 4294967297 is out of range: allowed an integer from 0 to "
              "2147483647");
    EXPECT_EQ(
        r->dropped[2],
        "config: state.toml:8: water.turbidity = 2.5 is out of range: allowed a number from 0 to 2 1/unit");
    // Text that is not TOML from line 1 has no key to keep; a line past the limits keeps the keys above it.
    EXPECT_FALSE(parse_config_keeping_valid("[rain\nintensity = 0.8\n", "state.toml"));
    std::string deep = "a";
    for (int i = 0; i < 20; ++i) deep += ".a";
    auto too_deep = parse_config_keeping_valid("[rain]\nintensity = 0.8\n" + deep + " = 1\n", "state.toml");
    ASSERT_TRUE(too_deep) << too_deep.error().message;
    ASSERT_EQ(too_deep->config.entries.size(), 1u);
    EXPECT_EQ(
        too_deep->syntax_error,
        "config: state.toml:3: key nests 22 levels; the limit is 16; the keys from line 3 on are dropped");
    EXPECT_FALSE(parse_config_keeping_valid(deep + " = 1\n", "state.toml")) << "past the limits from line 1";
}

TEST(ParseConfig, WrongTypeNamesFileLineAndExpectedType) {
    const Error s = config_error("[rain]\ndrop_count = \"ten\"\n");
    EXPECT_TRUE(has_text(s.message, "config: file.toml:2: rain.drop_count = "));
    EXPECT_TRUE(has_text(s.message, "ten"));
    EXPECT_TRUE(has_text(s.message, "has the wrong type: expected an integer from 1 to 128 drops"));

    const Error f = config_error("[rain]\ndrop_count = 2.5\n");
    EXPECT_EQ(f.message,
              "config: file.toml:2: rain.drop_count = 2.5 has the wrong type: expected an integer from 1 to "
              "128 drops");

    const Error b = config_error("[ground]\ncheckerboard = 1\n");
    EXPECT_EQ(b.message,
              "config: file.toml:2: ground.checkerboard = 1 has the wrong type: expected true or false");

    const Error c = config_error("[water]\n\n\ntint = [0.1, 0.2]\n");
    EXPECT_TRUE(has_text(c.message, "config: file.toml:4: water.tint = "));
    EXPECT_TRUE(
        has_text(c.message, "has the wrong type: expected three numbers [x, y, z], each from 0 to 1 rgb"));

    const Error v = config_error("[camera]\nposition = [1, \"2\", 3]\n");
    EXPECT_TRUE(has_text(v.message, "file.toml:2: camera.position = "));
    EXPECT_TRUE(has_text(v.message, "has the wrong type: expected three numbers"));

    const Error p = config_error("[environment]\nimage = 3\n");
    EXPECT_EQ(p.message,
              "config: file.toml:2: environment.image = 3 has the wrong type: expected text (path)");
}

TEST(ParseConfig, TopLevelKeyMustBeInASection) {
    const Error e = config_error("drop_count = 20\n");
    EXPECT_EQ(
        e.message,
        "config: file.toml:1: 'drop_count' must be inside a [section] (did you mean 'rain.drop_count'?)");
}

TEST(ParseConfig, TomlSyntaxErrorNamesFileAndLine) {
    const Error e = config_error("[rain]\ndrop_count = 20\nintensity = = 1\n", "/etc/puddle/puddle.toml");
    EXPECT_TRUE(has_text(e.message, "config: /etc/puddle/puddle.toml:3: "));
    const Error unclosed = config_error("[rain\ndrop_count = 20\n");
    EXPECT_TRUE(has_text(unclosed.message, "config: file.toml:1: "));
    const Error duplicate = config_error("[rain]\ndrop_count = 20\ndrop_count = 21\n");
    EXPECT_TRUE(has_text(duplicate.message, "config: file.toml:3: "));
}

TEST(ParseConfig, OneErrorIsReportedAndNoEntriesAreReturned) {
    // Two bad lines: one of them is named (toml++ visits keys sorted, so not necessarily the first line).
    auto r = parse_config("[rain]\ndrop_count = 20\nspeed = 99\nintensity = -1\n", "file.toml");
    ASSERT_FALSE(r);
    const std::string& m = r.error().message;
    EXPECT_TRUE(has_text(m, "file.toml:3: rain.speed = 99 is out of range") ||
                has_text(m, "file.toml:4: rain.intensity = -1 is out of range"))
        << m;
}

TEST(ParseConfig, SixCubemapPathsJoinWithBar) {
    auto r = parse_config(
        "[environment]\n"
        "image = [\"px.png\", \"nx.png\", \"py.png\", \"ny.png\", \"pz.png\", \"nz.png\"]\n",
        "file.toml");
    ASSERT_TRUE(r) << r.error().message;
    ASSERT_EQ(r->entries.size(), 1u);
    EXPECT_EQ(r->entries[0].id, ParamId::environment_image);
    EXPECT_EQ(std::get<std::string>(r->entries[0].value), "px.png|nx.png|py.png|ny.png|pz.png|nz.png");

    const Error mixed = config_error("[environment]\nimage = [\"px.png\", 2]\n");
    EXPECT_TRUE(has_text(mixed.message, "file.toml:2: environment.image = "));
    EXPECT_TRUE(has_text(mixed.message, "has the wrong type"));
    const Error empty = config_error("[environment]\nimage = []\n");
    EXPECT_TRUE(has_text(empty.message, "has the wrong type"));
}

TEST(LoadConfigFile, MissingFileNamesPathAndCannotOpen) {
    auto r = load_config_file("/nonexistent/puddle/none.toml");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ExitCode::Config);
    EXPECT_TRUE(has_text(r.error().message, "/nonexistent/puddle/none.toml"));
    EXPECT_TRUE(has_text(r.error().message, "cannot open"));
    EXPECT_EQ(r.error().message,
              "config: /nonexistent/puddle/none.toml: cannot open: No such file or directory");
}

TEST(LoadConfigFile, ReadsAFileAndUsesItsPathInMessages) {
    test::TempDir dir;
    const std::string good = dir.write("good.toml", "[look]\nvignette = 0.9\n");
    auto r = load_config_file(good);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ(r->path, good);
    ASSERT_EQ(r->entries.size(), 1u);
    EXPECT_EQ(std::get<float>(r->entries[0].value), 0.9f);

    const std::string bad = dir.write("bad.toml", "[look]\nvignette = 9\n");
    auto b = load_config_file(bad);
    ASSERT_FALSE(b);
    EXPECT_EQ(b.error().message,
              "config: " + bad + ":2: look.vignette = 9 is out of range: allowed a number from 0 to 1.4");
}

TEST(ParseAssignment, Good) {
    auto a = parse_assignment("rain.drop_count=20");
    ASSERT_TRUE(a) << a.error().message;
    EXPECT_EQ(a->id, ParamId::rain_drop_count);
    EXPECT_EQ(std::get<int>(a->value), 20);

    auto v = parse_assignment("camera.position=1,2,3");
    ASSERT_TRUE(v) << v.error().message;
    EXPECT_EQ(std::get<glm::vec3>(v->value), glm::vec3(1, 2, 3));

    auto b = parse_assignment("ground.checkerboard=off");
    ASSERT_TRUE(b) << b.error().message;
    EXPECT_FALSE(std::get<bool>(b->value));

    auto p = parse_assignment("environment.image=/a/b=c");  // only the first '=' splits
    ASSERT_TRUE(p) << p.error().message;
    EXPECT_EQ(std::get<std::string>(p->value), "/a/b=c");

    auto e = parse_assignment("ground.image=");
    ASSERT_TRUE(e) << e.error().message;
    EXPECT_EQ(std::get<std::string>(e->value), "");
}

TEST(ParseAssignment, Bad) {
    auto no_eq = parse_assignment("rain.drop_count");
    ASSERT_FALSE(no_eq);
    EXPECT_EQ(no_eq.error().code, ExitCode::Config);
    EXPECT_EQ(no_eq.error().message,
              "--set rain.drop_count: expected name=value, e.g. --set rain.drop_count=20");

    auto unknown = parse_assignment("rain.drop_cont=3");
    ASSERT_FALSE(unknown);
    EXPECT_EQ(unknown.error().code, ExitCode::Config);
    EXPECT_EQ(unknown.error().message,
              "--set rain.drop_cont=3: unknown parameter 'rain.drop_cont' (did you mean 'rain.drop_count'?)");

    auto range = parse_assignment("rain.drop_count=500");
    ASSERT_FALSE(range);
    EXPECT_EQ(range.error().code, ExitCode::Config);
    EXPECT_EQ(range.error().message,
              "--set: rain.drop_count = 500 is out of range: allowed an integer from 1 to 128 drops");

    auto type = parse_assignment("ground.checkerboard=maybe");
    ASSERT_FALSE(type);
    EXPECT_EQ(type.error().message,
              "--set: ground.checkerboard = \"maybe\" is not valid: expected true or false");

    // Past int's range: refused as out of range, naming the value as written.
    auto seed = parse_assignment("rain.seed=4294967297");
    ASSERT_FALSE(seed);
    EXPECT_EQ(seed.error().message,
              "--set: rain.seed = 4294967297 is out of range: allowed an integer from 0 to 2147483647");
    auto huge = parse_assignment("rain.seed=99999999999999999999");
    ASSERT_FALSE(huge);
    EXPECT_EQ(
        huge.error().message,
        "--set: rain.seed = 99999999999999999999 is out of range: allowed an integer from 0 to 2147483647");
    auto big_float = parse_assignment("rain.intensity=1e39");  // past a float, not infinity
    ASSERT_FALSE(big_float);
    EXPECT_EQ(big_float.error().message,
              "--set: rain.intensity = 1e+39 is out of range: allowed a number from 0 to 4 height");
    auto big_vec = parse_assignment("camera.position=1,1e39,3");
    ASSERT_FALSE(big_vec);
    EXPECT_EQ(big_vec.error().message,
              "--set: camera.position = 1,1e39,3 is out of range: allowed three numbers [x, y, z], each from "
              "-1000 to "
              "1000 units");

    auto empty = parse_assignment("=3");
    ASSERT_FALSE(empty);
    EXPECT_TRUE(has_text(empty.error().message, "unknown parameter ''"));
}

// The shipped, documented config: it parses, every key exists, and it sets every parameter (paths
// excepted: their default is empty, so they are commented-out examples) to its default value, so the
// file is a safe starting point and stays in step with params.def.
TEST(ShippedConfig, ParsesAndSetsEveryParameterToItsDefault) {
    const std::string path = PUDDLE_SOURCE_DIR "/config/puddle.toml";
    auto r = load_config_file(path);
    ASSERT_TRUE(r) << r.error().message;
    std::map<ParamId, int> seen;
    for (const ConfigEntry& e : r->entries) {
        const ParamDecl& d = decl(e.id);
        ASSERT_NE(find_param(d.name), nullptr);
        EXPECT_EQ(++seen[e.id], 1) << d.name << " appears twice (line " << e.line << ")";
        EXPECT_EQ(e.value, d.default_value)
            << path << ":" << e.line << ": " << d.name << " = " << format_value(e.value) << ", default "
            << format_value(d.default_value);
    }
    for (const ParamDecl& d : param_decls()) {
        if (d.kind == ParamKind::Path) continue;
        EXPECT_EQ(seen.count(d.id), 1u) << d.name << " is missing from " << path;
    }
}

TEST(ShippedConfig, MentionsEveryPathParameterAsAnExample) {
    std::ifstream in(PUDDLE_SOURCE_DIR "/config/puddle.toml");
    ASSERT_TRUE(in);
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    for (const ParamDecl& d : param_decls()) {
        if (d.kind != ParamKind::Path) continue;
        const std::string key(d.name.substr(d.name.find('.') + 1));
        EXPECT_TRUE(has_text(s, "# " + key + " = ")) << d.name << " has no commented-out example";
    }
    EXPECT_TRUE(has_text(s, "--list-params"));
    EXPECT_TRUE(has_text(s, "--set"));
}

}  // namespace
}  // namespace puddle::params
