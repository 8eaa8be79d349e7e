#pragma once
// The names the kernel, xrandr and Puddle's config give DRM connectors and modes. Private to the
// platform layer: it needs libdrm's types, which stay out of drm_inventory.hpp so that `--check` (the
// app) can list cards without libdrm's headers.

#include <xf86drmMode.h>

#include <string>

namespace puddle::platform {

// "HDMI-A-1", "DP-2", "Virtual-1": the names the kernel and xrandr use, and display.connector takes.
std::string connector_name(const drmModeConnector& c);
// "1920x1080@60", as display.mode takes it.
std::string mode_name(const drmModeModeInfo& m);

}  // namespace puddle::platform
