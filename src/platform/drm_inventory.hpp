#pragma once
// What DRM/KMS hardware a board has: the cards in the kernel's order (for the kms backend's choice),
// and for `puddle --check` each card, its connectors, their state and modes. Read-only: nothing is
// set, so it is safe while another program owns the screen.

#include <string>
#include <vector>

namespace puddle::platform {

struct DrmConnectorInfo {
    std::string name;  // "HDMI-A-1", as display.connector takes it
    bool connected = false;
    std::vector<std::string> modes;  // "1920x1080@60", preferred first
};

// What a card node turned out to be.
enum class DrmCardStatus {
    Display,     // a KMS device: its connectors are listed (there may be none connected)
    NoOutputs,   // opened, but it reports no KMS resources: a render-only GPU (or not a DRM device)
    CannotOpen,  // open(2) failed: permissions, or the node is gone
};

struct DrmCardInfo {
    std::string path;    // /dev/dri/card0
    std::string driver;  // "vc4", "virtio_gpu"; empty when the kernel did not say
    DrmCardStatus status = DrmCardStatus::Display;
    std::string error;  // why, when status is not Display: "cannot open: Permission denied (...)"
    std::vector<DrmConnectorInfo> connectors;
};

// The card nodes in `folder` (card0, card1, ..., card10: by number, not as text; renderD* and other
// names are left out), as paths.
std::vector<std::string> drm_card_paths(const std::string& folder = "/dev/dri");

// Reads the card open on `fd` (driver, status Display or NoOutputs, connectors); `fd` stays open.
DrmCardInfo read_drm_card(int fd, std::string path);

// Every card in `folder`, in drm_card_paths' order, each opened and read, then closed again.
std::vector<DrmCardInfo> list_drm_cards(const std::string& folder = "/dev/dri");

}  // namespace puddle::platform
