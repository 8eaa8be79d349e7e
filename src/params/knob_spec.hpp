#pragma once
// A knob as the config declares it (`[[knob]]`): which GPIO lines, what kind of control, and what it
// changes. Plain data; the GPIO side (src/io/) turns line events into parameter changes.

#include <optional>
#include <string>

#include "params/registry.hpp"

namespace puddle::params {

enum class KnobKind { Encoder, Button, Switch };
enum class ButtonAction { NextPreset, PreviousPreset, Reset, Toggle, SaveState };
// Pull-up/pull-down where the GPIO driver supports it; `AsIs` leaves the line's bias alone.
enum class LineBias { AsIs, PullUp, PullDown, Disabled };

struct KnobSpec {
    KnobKind kind = KnobKind::Encoder;
    int config_line = 0;             // where the [[knob]] starts, for messages
    std::string chip = "gpiochip0";  // name, /dev path, label or number
    std::string line;    // button/switch line, encoder line A: an offset ("17") or a line name ("GPIO17")
    std::string line_b;  // encoder line B
    bool active_low = false;
    LineBias bias = LineBias::AsIs;
    std::optional<ParamId> param;  // encoder target; reset/toggle/switch parameter
    double step = 0;               // encoder: change per detent (0: 1/50 of the range)
    double acceleration = 0;       // encoder: 0 none; 1 doubles the step at 8 detents/s
    ButtonAction action = ButtonAction::NextPreset;
    int debounce_ms = 20;  // button and switch

    bool operator==(const KnobSpec&) const = default;
    // "encoder rain.intensity on gpiochip0 lines 17/18" (for logs).
    std::string describe() const;
};

std::string_view knob_kind_name(KnobKind k);
std::string_view button_action_name(ButtonAction a);
std::string_view bias_name(LineBias b);

}  // namespace puddle::params
