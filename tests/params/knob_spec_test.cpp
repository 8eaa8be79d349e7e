// A knob as the config declares it (params/knob_spec.hpp): the one line logs and --check show for each
// kind, and names that are exactly what a config may write.
#include "params/knob_spec.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "params/config_loader.hpp"

namespace puddle::params {
namespace {

TEST(KnobSpec, DescribesEachKindWithItsTargetChipAndLines) {
    const KnobSpec encoder{
        .kind = KnobKind::Encoder, .line = "17", .line_b = "GPIO18", .param = ParamId::rain_intensity};
    EXPECT_EQ(encoder.describe(), "encoder rain.intensity on gpiochip0 lines 17/GPIO18");
    const KnobSpec save{
        .kind = KnobKind::Button, .chip = "pinctrl-bcm2711", .line = "27", .action = ButtonAction::SaveState};
    EXPECT_EQ(save.describe(), "button save on pinctrl-bcm2711 line 27");
    const KnobSpec reset{.kind = KnobKind::Button,
                         .line = "5",
                         .param = ParamId::rain_intensity,
                         .action = ButtonAction::Reset};
    EXPECT_EQ(reset.describe(), "button reset rain.intensity on gpiochip0 line 5");
    const KnobSpec toggle{.kind = KnobKind::Switch, .line = "22", .param = ParamId::ground_checkerboard};
    EXPECT_EQ(toggle.describe(), "switch ground.checkerboard on gpiochip0 line 22");
}

// Each name the code prints is one the config parser takes back to the same value: fails if the parser's
// list of actions, biases or kinds left one out (seen with LineBias::Disabled dropped from it).
TEST(KnobSpec, EveryActionAndBiasNameIsWhatTheConfigAccepts) {
    for (const ButtonAction a : {ButtonAction::NextPreset, ButtonAction::PreviousPreset, ButtonAction::Reset,
                                 ButtonAction::Toggle, ButtonAction::SaveState}) {
        for (const LineBias b : {LineBias::AsIs, LineBias::PullUp, LineBias::PullDown, LineBias::Disabled}) {
            const std::string text = fmt::format(
                "[[knob]]\nkind = \"button\"\nline = 3\naction = \"{}\"\nparam = "
                "\"ground.checkerboard\"\nbias = \"{}\"\n",
                button_action_name(a), bias_name(b));
            auto c = parse_config(text, "k.toml");
            ASSERT_TRUE(c) << c.error().message;
            ASSERT_EQ(c->knobs.size(), 1u);
            EXPECT_EQ(c->knobs[0].action, a) << button_action_name(a);
            EXPECT_EQ(c->knobs[0].bias, b) << bias_name(b);
            EXPECT_EQ(c->knobs[0].kind, KnobKind::Button);
        }
    }
    for (const KnobKind k : {KnobKind::Encoder, KnobKind::Button, KnobKind::Switch}) {
        auto c = parse_config(fmt::format("[[knob]]\nkind = \"{}\"\n", knob_kind_name(k)), "k.toml");
        ASSERT_FALSE(c);
        EXPECT_EQ(c.error().message.find("kind must be"), std::string::npos)
            << knob_kind_name(k) << " is a kind: " << c.error().message;
    }
}

}  // namespace
}  // namespace puddle::params
