#include "platform/drm_inventory.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>

#include "platform/drm_names.hpp"
#include "util/unique_fd.hpp"

namespace puddle::platform {

std::vector<std::string> drm_card_paths(const std::string& folder) {
    std::vector<std::pair<int, std::string>> cards;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        if (!name.starts_with("card")) continue;
        int number = 0;
        const char* digits = name.data() + 4;
        const auto [end, err] = std::from_chars(digits, name.data() + name.size(), number);
        if (err != std::errc{} || end != name.data() + name.size()) continue;
        cards.emplace_back(number, entry.path().string());
    }
    std::sort(cards.begin(), cards.end());
    std::vector<std::string> paths;
    for (auto& card : cards) paths.push_back(std::move(card.second));
    return paths;
}

std::string connector_name(const drmModeConnector& c) {
    const char* type = drmModeGetConnectorTypeName(c.connector_type);
    return fmt::format("{}-{}", type ? type : "Unknown", c.connector_type_id);
}

std::string mode_name(const drmModeModeInfo& m) {
    return fmt::format("{}x{}@{}", m.hdisplay, m.vdisplay, m.vrefresh);
}

DrmCardInfo read_drm_card(int fd, std::string path) {
    DrmCardInfo card{std::move(path)};
    if (drmVersionPtr v = drmGetVersion(fd)) {
        card.driver = v->name ? v->name : "";
        drmFreeVersion(v);
    }
    drmModeRes* res = drmModeGetResources(fd);
    if (!res) {
        card.status = DrmCardStatus::NoOutputs;
        card.error = "no display outputs (a render-only GPU)";
        return card;
    }
    for (int i = 0; i < res->count_connectors; ++i) {
        drmModeConnector* c = drmModeGetConnector(fd, res->connectors[i]);
        if (!c) continue;
        DrmConnectorInfo info{connector_name(*c), c->connection == DRM_MODE_CONNECTED, {}};
        for (int m = 0; m < c->count_modes; ++m) {
            const drmModeModeInfo& mode = c->modes[m];
            std::string text = mode_name(mode);
            if (mode.type & DRM_MODE_TYPE_PREFERRED)
                info.modes.insert(info.modes.begin(), text + " (preferred)");
            else if (std::find(info.modes.begin(), info.modes.end(), text) == info.modes.end())
                info.modes.push_back(text);
        }
        card.connectors.push_back(std::move(info));
        drmModeFreeConnector(c);
    }
    drmModeFreeResources(res);
    return card;
}

std::vector<DrmCardInfo> list_drm_cards(const std::string& folder) {
    std::vector<DrmCardInfo> cards;
    for (std::string& path : drm_card_paths(folder)) {
        const UniqueFd fd(::open(path.c_str(), O_RDWR | O_CLOEXEC));
        if (!fd) {
            const int err = errno;
            cards.push_back({.path = std::move(path),
                             .status = DrmCardStatus::CannotOpen,
                             .error = fmt::format("cannot open: {}{}", std::strerror(err),
                                                  err == EACCES ? " (add the user to group video)" : "")});
            continue;
        }
        cards.push_back(read_drm_card(fd.get(), std::move(path)));
    }
    return cards;
}

}  // namespace puddle::platform
