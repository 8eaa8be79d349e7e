#include "params/knob_spec.hpp"

#include <fmt/format.h>

namespace puddle::params {

std::string_view knob_kind_name(KnobKind k) {
    switch (k) {
        case KnobKind::Encoder:
            return "encoder";
        case KnobKind::Button:
            return "button";
        case KnobKind::Switch:
            return "switch";
    }
    return "?";
}

std::string_view button_action_name(ButtonAction a) {
    switch (a) {
        case ButtonAction::NextPreset:
            return "next-preset";
        case ButtonAction::PreviousPreset:
            return "previous-preset";
        case ButtonAction::Reset:
            return "reset";
        case ButtonAction::Toggle:
            return "toggle";
        case ButtonAction::SaveState:
            return "save";
    }
    return "?";
}

std::string_view bias_name(LineBias b) {
    switch (b) {
        case LineBias::AsIs:
            return "as-is";
        case LineBias::PullUp:
            return "pull-up";
        case LineBias::PullDown:
            return "pull-down";
        case LineBias::Disabled:
            return "disabled";
    }
    return "?";
}

std::string KnobSpec::describe() const {
    const std::string target = param ? std::string(decl(*param).name) : std::string();
    switch (kind) {
        case KnobKind::Encoder:
            return fmt::format("encoder {} on {} lines {}/{}", target, chip, line, line_b);
        case KnobKind::Button:
            return fmt::format("button {}{}{} on {} line {}", button_action_name(action),
                               target.empty() ? "" : " ", target, chip, line);
        case KnobKind::Switch:
            return fmt::format("switch {} on {} line {}", target, chip, line);
    }
    return "knob";
}

}  // namespace puddle::params
