// Issue 15, fault 5, through the real binary: saved state is the user's data. A bad key is dropped and
// reported and every valid one kept; the original is set aside under a name that never overwrites an
// earlier copy; commands that only read (--print-config, --check, --list-params) change nothing on disk.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "support/test_support.hpp"

namespace puddle::test {
namespace {

namespace fs = std::filesystem;

// Every file under `dir` with its bytes.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        files[fs::relative(e.path(), dir).string()] = e.is_regular_file() ? read_file(e.path()) : "(folder)";
    return files;
}

std::vector<std::string> set_aside_copies(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().starts_with("state.toml.bad-"))
            names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

constexpr const char* knob_config = R"([[knob]]
kind = "encoder"
a = 17
b = 18
param = "rain.intensity"
step = 0.05
)";
// As ../shared/cases/state: one good value each side of a bad one.
constexpr const char* out_of_range_state =
    "[rain]\nintensity = 0.8\n[look]\nvignette = 1.2\n[water]\nturbidity = 2.5\n";
constexpr const char* unknown_key_state = "[rain]\nintensity = 0.7\nwind = 0.5\n[look]\nvignette = 1.1\n";

struct StateFolder {
    TempDir dir;
    std::string config, script, state_dir, state, args;
    StateFolder() {
        config = dir.write("puddle.toml", knob_config);
        script = dir.write("gpio.txt", "");
        fs::create_directories(dir / "state");
        state_dir = (dir / "state").string();
        state = (dir / "state" / "state.toml").string();
        args = "--config " + config + " --gpio mock:" + script + " --state " + state;
    }
};

TEST(SavedStateEndToEnd, ReadOnlyCommandsNeverMoveRewriteOrCreateState) {
    StateFolder s;
    std::ofstream(s.state) << unknown_key_state;
    std::ofstream(s.dir / "state" / "state.toml.bad-0001-20260101T000000Z") << "an earlier copy";
    const auto before = snapshot(s.state_dir);

    const auto print = run_puddle(s.args + " --print-config");
    EXPECT_EQ(print.exit_code, 0) << print.output;
    EXPECT_NE(print.output.find("unknown key 'rain.wind'"), std::string::npos) << print.output;
    EXPECT_NE(print.output.find("rain.intensity             = 0.7                      # knob"),
              std::string::npos)
        << print.output;
    EXPECT_EQ(snapshot(s.state_dir), before) << "--print-config changed the state folder";

    const auto check = run_puddle(s.args + " --check");
    EXPECT_NE(check.output.find("[config]"), std::string::npos) << check.output;
    EXPECT_EQ(snapshot(s.state_dir), before) << "--check changed the state folder";

    const auto list = run_puddle(s.args + " --list-params");
    EXPECT_EQ(list.exit_code, 0) << list.output;
    EXPECT_EQ(snapshot(s.state_dir), before) << "--list-params changed the state folder";

    // Nor do they create a state file where there is none.
    fs::remove(s.state);
    const auto empty = snapshot(s.state_dir);
    for (const char* flag : {" --print-config", " --check", " --list-params"}) {
        run_puddle(s.args + flag);
        EXPECT_EQ(snapshot(s.state_dir), empty) << flag;
    }
}

TEST(SavedStateEndToEnd, ARunKeepsTheValidValuesAndSetsEachBadFileAsideUnderItsOwnName) {
    StateFolder s;
    const std::string run = "-b headless --size 64x36 --frames 3 " + s.args;
    std::ofstream(s.state) << out_of_range_state;
    const auto first = run_puddle(run);
    ASSERT_EQ(first.exit_code, 0) << first.output;
    EXPECT_NE(
        first.output.find("state: " + s.state +
                          ":6: water.turbidity = 2.5 is out of range: allowed a number from 0 to 2 1/unit; "
                          "dropped that value, kept the others"),
        std::string::npos)
        << first.output;
    // The state now holds the valid values, and the original is kept.
    EXPECT_EQ(read_file(s.state),
              "# Written by puddle: what the knobs changed. Delete this file to forget it.\n"
              "[rain]\nintensity = 0.8\n[look]\nvignette = 1.2\n");
    auto copies = set_aside_copies(s.state_dir);
    ASSERT_EQ(copies.size(), 1u);
    EXPECT_EQ(read_file(s.dir / "state" / copies[0]), out_of_range_state);

    // A second bad state file does not overwrite the first one's copy.
    std::ofstream(s.state) << unknown_key_state;
    const auto second = run_puddle(run);
    ASSERT_EQ(second.exit_code, 0) << second.output;
    EXPECT_EQ(read_file(s.state),
              "# Written by puddle: what the knobs changed. Delete this file to forget it.\n"
              "[rain]\nintensity = 0.7\n[look]\nvignette = 1.1\n");
    copies = set_aside_copies(s.state_dir);
    ASSERT_EQ(copies.size(), 2u);
    EXPECT_EQ(read_file(s.dir / "state" / copies[0]), out_of_range_state);
    EXPECT_EQ(read_file(s.dir / "state" / copies[1]), unknown_key_state);

    // A clean state is neither set aside nor rewritten.
    const auto before = snapshot(s.state_dir);
    const auto third = run_puddle(run);
    ASSERT_EQ(third.exit_code, 0) << third.output;
    EXPECT_EQ(snapshot(s.state_dir), before);
}

}  // namespace
}  // namespace puddle::test
