#pragma once
// Which parameters the broker may set (remote.writable): comma-separated names ("rain.seed") or prefix
// patterns ("rain.*"), or "*" for everything allowed at all. Settings of the device itself are never
// writable, whatever the patterns say: remote.* (the broker, its credentials), display.* (the screen a
// kiosk drives), environment.camera_* (which device file is opened) and wall.* (where this screen sits in
// a video wall: one message to a fleet would give every screen the same place).

#include <string>
#include <string_view>
#include <vector>

#include "params/registry.hpp"

namespace puddle::remote {

class WritablePatterns {
public:
    WritablePatterns() = default;
    // "rain.*, look.vignette": blanks around the commas are ignored, empty items skipped.
    explicit WritablePatterns(std::string_view text);
    bool allows(const params::ParamDecl& d) const;
    // Never writable over MQTT, whatever the patterns.
    static bool device_setting(std::string_view name);

private:
    std::vector<std::string> patterns_;
};

}  // namespace puddle::remote
