#include "platform/kms_mode.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <charconv>
#include <vector>

#include "platform/drm_names.hpp"

namespace puddle::platform {

namespace {

bool matches(const drmModeModeInfo& m, const ModeSpec& spec) {
    return m.hdisplay == spec.width && m.vdisplay == spec.height &&
           (spec.refresh == 0 || static_cast<int>(m.vrefresh) == spec.refresh);
}

std::string list_modes(const drmModeConnector& c) {
    std::vector<std::string> names;
    for (int i = 0; i < c.count_modes; ++i) {
        std::string name = mode_name(c.modes[i]);
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(std::move(name));
    }
    return fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace

std::optional<ModeSpec> parse_mode(std::string_view text) {
    ModeSpec spec;
    const char* p = text.data();
    const char* end = text.data() + text.size();
    auto number = [&](int& out) {
        const auto [next, err] = std::from_chars(p, end, out);
        if (err != std::errc{} || out <= 0) return false;
        p = next;
        return true;
    };
    if (!number(spec.width) || p == end || *p++ != 'x' || !number(spec.height)) return std::nullopt;
    if (p != end && (*p++ != '@' || !number(spec.refresh))) return std::nullopt;
    if (p != end) return std::nullopt;
    return spec;
}

bool is_connected(const drmModeConnector& c) {
    return c.connection == DRM_MODE_CONNECTED && c.count_modes > 0;
}

const drmModeModeInfo* find_mode(const drmModeConnector& c, const std::optional<ModeSpec>& spec) {
    const drmModeModeInfo* found = nullptr;
    for (int i = 0; i < c.count_modes; ++i) {
        const drmModeModeInfo& m = c.modes[i];
        if (spec && !matches(m, *spec)) continue;
        if (m.type & DRM_MODE_TYPE_PREFERRED) return &m;
        if (!found) found = &m;
    }
    return found;
}

Result<drmModeModeInfo> pick_mode(const std::string& card, const drmModeConnector& c,
                                  const DisplayOptions& options) {
    const std::string name = connector_name(c);
    if (!options.mode.empty()) {
        const auto spec = parse_mode(options.mode);
        if (!spec)
            return make_error(ExitCode::Display, "kms: mode '{}' is not WIDTHxHEIGHT or WIDTHxHEIGHT@HZ",
                              options.mode);
        if (const auto* m = find_mode(c, spec)) return *m;
        return make_error(ExitCode::Display, "kms: {}: {} has no mode {}; available: {}", card, name,
                          options.mode, list_modes(c));
    }
    if (options.size.x > 0 && options.size.y > 0) {
        if (const auto* m = find_mode(c, ModeSpec{options.size.x, options.size.y, 0})) return *m;
        spdlog::warn("kms: {}: {} has no {}x{} mode, using its preferred one", card, name, options.size.x,
                     options.size.y);
    }
    if (const auto* m = find_mode(c, std::nullopt)) return *m;
    return make_error(ExitCode::Display, "kms: {}: {} reports no modes", card, name);
}

Result<std::size_t> pick_connector(std::span<const drmModeConnector* const> connectors,
                                   const std::string& card, const std::string& wanted) {
    std::vector<std::string> listing;
    for (std::size_t i = 0; i < connectors.size(); ++i) {
        const drmModeConnector& c = *connectors[i];
        const std::string name = connector_name(c);
        if (wanted.empty() ? is_connected(c) : name == wanted) {
            if (!is_connected(c))
                return make_error(ExitCode::Display, "kms: {}: connector {} is not connected", card, name);
            return i;
        }
        listing.push_back(fmt::format("{} ({})", name, is_connected(c) ? "connected" : "disconnected"));
    }
    const std::string available = listing.empty() ? "none" : fmt::format("{}", fmt::join(listing, ", "));
    if (wanted.empty())
        return make_error(ExitCode::Display, "kms: {}: no connected connector; connectors: {}", card,
                          available);
    return make_error(ExitCode::Display, "kms: {}: no connector named {}; connectors: {}", card, wanted,
                      available);
}

}  // namespace puddle::platform
