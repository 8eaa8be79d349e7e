#pragma once
// What DRM/KMS hardware a board has, for `puddle --check`: each card, its connectors, their state and
// modes. Read-only: nothing is set, so it is safe while another program owns the screen.

#include <string>
#include <vector>

namespace puddle::platform {

struct DrmConnectorInfo {
    std::string name;   // "HDMI-A-1", as display.connector takes it
    bool connected = false;
    std::vector<std::string> modes;  // "1920x1080@60", preferred first
};

struct DrmCardInfo {
    std::string path;   // /dev/dri/card0
    std::string driver;
    std::string error;  // set when the card could not be read (permissions, not a KMS device)
    std::vector<DrmConnectorInfo> connectors;
};

std::vector<DrmCardInfo> list_drm_cards();

}  // namespace puddle::platform
