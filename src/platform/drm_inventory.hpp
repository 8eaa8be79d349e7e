#pragma once
// What DRM/KMS hardware a board has: the cards in the kernel's order (for the kms backend's choice),
// and for `puddle --check` each card, its connectors, their state and modes. Read-only: nothing is
// set, so it is safe while another program owns the screen.

#include <xf86drmMode.h>

#include <string>
#include <vector>

namespace puddle::platform {

struct DrmConnectorInfo {
    std::string name;  // "HDMI-A-1", as display.connector takes it
    bool connected = false;
    std::vector<std::string> modes;  // "1920x1080@60", preferred first
};

struct DrmCardInfo {
    std::string path;  // /dev/dri/card0
    std::string driver;
    std::string error;  // set when the card could not be read (permissions, not a KMS device)
    std::vector<DrmConnectorInfo> connectors;
};

// The card nodes in `folder` (card0, card1, ..., card10: by number, not as text; renderD* and other
// names are left out), as paths.
std::vector<std::string> drm_card_paths(const std::string& folder = "/dev/dri");

std::vector<DrmCardInfo> list_drm_cards();

// "HDMI-A-1", "DP-2", "Virtual-1": the names the kernel and xrandr use, and display.connector takes.
std::string connector_name(const drmModeConnector& c);
// "1920x1080@60", as display.mode takes it.
std::string mode_name(const drmModeModeInfo& m);

}  // namespace puddle::platform
