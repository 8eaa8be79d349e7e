// Tests for src/app/app.hpp, load_tuning: the layers the options ask for. --seed and --camera become
// command-line entries that a --set still overrides; a bad --set or --gpio is a config error naming it;
// the saved knob state is read only when the config has knobs. Every run names a config file of its own,
// so /etc/puddle/puddle.toml never takes part.
#include "app/app.hpp"

#include <gtest/gtest.h>

#include <string>

#include "support/test_support.hpp"

namespace puddle::app {
namespace {

using params::ParamId;

class LoadTuning : public ::testing::Test {
protected:
    // Options with `config` (TOML) as the config file and a state file holding rain.intensity = 1.5.
    CliOptions options(const std::string& config) {
        CliOptions o;
        o.config_path = dir_.write("puddle.toml", config);
        o.state_path = dir_.write("state.toml", "[rain]\nintensity = 1.5\n");
        o.gpio = "mock:" + dir_.write("gpio-script", "");
        return o;
    }
    static params::Params compose(const CliOptions& o) {
        auto tuning = load_tuning(o, StartFor::print_config);
        EXPECT_TRUE(tuning.ok()) << tuning.error().message;
        return tuning.ok() ? tuning->layers.compose() : params::Params{};
    }
    test::TempDir dir_;
};

const std::string knob_config = R"([[knob]]
kind = "encoder"
chip = "gpiochip0"
a = 17
b = 18
param = "rain.intensity"
step = 0.05
)";

TEST_F(LoadTuning, SeedAndCameraAreCommandLineEntriesOverTheConfig) {
    CliOptions o = options("[rain]\nseed = 5\n[environment]\ncamera_device = \"/dev/video3\"\n");
    EXPECT_EQ(compose(o).get<ParamId::rain_seed>(), 5) << "the config alone";
    o.seed = 42;
    o.camera = "/dev/video7";
    const params::Params p = compose(o);
    EXPECT_EQ(p.get<ParamId::rain_seed>(), 42);
    EXPECT_EQ(p.get<ParamId::environment_source>(), params::EnvironmentSource::camera);
    EXPECT_EQ(p.get<ParamId::environment_camera_device>(), "/dev/video7");
}

TEST_F(LoadTuning, ASetStillOverridesSeedAndCamera) {
    CliOptions o = options("");
    o.seed = 42;
    o.camera = "/dev/video7";
    o.sets = {"rain.seed=7", "environment.camera_device=/dev/video9", "environment.source=cubemap"};
    const params::Params p = compose(o);
    EXPECT_EQ(p.get<ParamId::rain_seed>(), 7);
    EXPECT_EQ(p.get<ParamId::environment_camera_device>(), "/dev/video9");
    EXPECT_EQ(p.get<ParamId::environment_source>(), params::EnvironmentSource::cubemap);
}

TEST_F(LoadTuning, ABadSetIsAConfigErrorNamingIt) {
    CliOptions o = options("");
    o.sets = {"rain.seed=7", "rain.no_such=1"};
    auto unknown = load_tuning(o, StartFor::print_config);
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().code, ExitCode::Config);
    EXPECT_TRUE(unknown.error().message.starts_with("--set rain.no_such=1: unknown parameter 'rain.no_such'"))
        << unknown.error().message;
    o.sets = {"rain.seed"};
    auto no_value = load_tuning(o, StartFor::print_config);
    ASSERT_FALSE(no_value.ok());
    EXPECT_EQ(no_value.error().code, ExitCode::Config);
    EXPECT_TRUE(no_value.error().message.starts_with("--set rain.seed: expected name=value"))
        << no_value.error().message;
}

TEST_F(LoadTuning, TheSavedStateIsReadOnlyWhenTheConfigHasKnobs) {
    CliOptions o = options("[rain]\nintensity = 0.5\n");
    auto without = load_tuning(o, StartFor::print_config);
    ASSERT_TRUE(without.ok()) << without.error().message;
    EXPECT_FALSE(without->state.has_value()) << "no knobs: no state store";
    EXPECT_FLOAT_EQ(without->layers.compose().get<ParamId::rain_intensity>(), 0.5f)
        << "the state file unread";

    o = options(knob_config + "[rain]\nintensity = 0.5\n");
    auto with = load_tuning(o, StartFor::print_config);
    ASSERT_TRUE(with.ok()) << with.error().message;
    ASSERT_TRUE(with->state.has_value());
    EXPECT_EQ(with->state->path(), o.state_path);
    EXPECT_FLOAT_EQ(with->layers.compose().get<ParamId::rain_intensity>(), 1.5f) << "the knob's saved value";
    EXPECT_EQ(with->gpio, nullptr) << "--print-config opens no GPIO chip";
    auto run = load_tuning(o, StartFor::run);
    ASSERT_TRUE(run.ok()) << run.error().message;
    EXPECT_NE(run->gpio, nullptr) << "the knobs' backend";
    EXPECT_FLOAT_EQ(run->layers.compose().get<ParamId::rain_intensity>(), 1.5f);
}

// --check assembles what the run would (app/startup.hpp) but reads no saved state (it reports on the file
// itself) and opens no GPIO.
TEST_F(LoadTuning, ACheckReadsNoSavedStateAndOpensNoGpio) {
    CliOptions o = options(knob_config + "[rain]\nintensity = 0.5\n");
    auto check = load_tuning(o, StartFor::check);
    ASSERT_TRUE(check.ok()) << check.error().message;
    EXPECT_FALSE(check->state.has_value());
    EXPECT_EQ(check->gpio, nullptr);
    EXPECT_FLOAT_EQ(check->layers.compose().get<ParamId::rain_intensity>(), 0.5f) << "the config's, no knob";
}

TEST_F(LoadTuning, AGpioTypoIsAConfigErrorEvenWithoutKnobs) {
    CliOptions o = options("");
    o.gpio = "gpoid";
    auto r = load_tuning(o, StartFor::print_config);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ExitCode::Config);
    EXPECT_TRUE(r.error().message.starts_with("--gpio gpoid: expected \"gpiod\" or \"mock:PATH\""))
        << r.error().message;
}

// Start-up refuses a screen placed off the wall (params/wall_check.hpp), here by a --set over the config.
TEST_F(LoadTuning, AScreenOffTheWallIsAConfigError) {
    CliOptions o = options("[wall]\ncolumns = 2\nrows = 2\n");
    o.sets = {"wall.row=1", "wall.column=2"};
    auto r = load_tuning(o, StartFor::print_config);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ExitCode::Config);
    EXPECT_EQ(
        r.error().message,
        "--set wall.column=2: wall.column = 2 is out of range: allowed 0 to 1 (0-based; wall.columns = 2, "
        "from config: " +
            o.config_path + ":2)");
    o.sets = {"wall.row=1", "wall.column=1"};
    EXPECT_EQ(compose(o).get<ParamId::wall_column>(), 1);
}

TEST_F(LoadTuning, AConfigErrorIsReturnedAsItIs) {
    CliOptions o = options("[rain]\nseed = \"five\"\n");
    auto r = load_tuning(o, StartFor::print_config);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ExitCode::Config);
    EXPECT_NE(r.error().message.find(o.config_path), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find("rain.seed"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace puddle::app
