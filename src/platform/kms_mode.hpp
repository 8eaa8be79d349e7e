#pragma once
// The kms backend's choices that need no device: which connector shows the picture and which of its modes
// is used, from display.connector, display.mode and --size. Pure functions over what libdrm reports
// (drmModeConnector, drmModeModeInfo), so tests build the data by hand; kms_display.cpp reads it from the
// card and does the modeset.

#include <xf86drmMode.h>

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "platform/display.hpp"
#include "util/result.hpp"

namespace puddle::platform {

// A mode as display.mode writes it: pixels wide and high, and the vertical refresh in whole Hz.
struct ModeSpec {
    int width = 0;
    int height = 0;
    int refresh = 0;  // 0: any
};

// "1920x1080" or "1920x1080@60" (each number positive, nothing before or after); nothing for any other text.
std::optional<ModeSpec> parse_mode(std::string_view text);

// A connector that can show a picture: connected, with at least one mode.
bool is_connected(const drmModeConnector& c);

// Among the modes of `c` that match `spec` (all modes when there is none): the first one the connector
// marks preferred (DRM_MODE_TYPE_PREFERRED), else the first that matches; null when none matches.
const drmModeModeInfo* find_mode(const drmModeConnector& c, const std::optional<ModeSpec>& spec);

// The mode the kms backend sets on `c` (of `card`, for messages):
// - options.mode given: the mode it names (find_mode). Errors (ExitCode::Display): "kms: mode 'TEXT' is not
//   WIDTHxHEIGHT or WIDTHxHEIGHT@HZ"; "kms: CARD: CONNECTOR has no mode TEXT; available: 1920x1080@60, ...".
// - else options.size: the mode of that size (any refresh), or, with a warning logged, the preferred one;
// - else the preferred mode. Error: "kms: CARD: CONNECTOR reports no modes".
Result<drmModeModeInfo> pick_mode(const std::string& card, const drmModeConnector& c,
                                  const DisplayOptions& options);

// Which of `connectors` (the card's, in its order) shows the picture: the one named `wanted` ("HDMI-A-1",
// as connector_name() spells it), or with `wanted` empty the first connected one. Returns its index.
// Errors (ExitCode::Display), listing every connector with its state:
// "kms: CARD: connector NAME is not connected"; "kms: CARD: no connected connector; connectors: HDMI-A-1
// (disconnected), ..." ("none" for a card without connectors); "kms: CARD: no connector named NAME;
// connectors: ...".
Result<std::size_t> pick_connector(std::span<const drmModeConnector* const> connectors,
                                   const std::string& card, const std::string& wanted);

}  // namespace puddle::platform
