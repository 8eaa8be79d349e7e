#include "platform/drm_inventory.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

namespace puddle::platform {

std::vector<DrmCardInfo> list_drm_cards() {
    std::vector<DrmCardInfo> cards;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator("/dev/dri", ec))
        if (entry.path().filename().string().starts_with("card")) cards.push_back({entry.path().string()});
    std::sort(cards.begin(), cards.end(), [](const auto& a, const auto& b) { return a.path < b.path; });
    for (DrmCardInfo& card : cards) {
        const int fd = ::open(card.path.c_str(), O_RDWR | O_CLOEXEC);
        if (fd < 0) {
            card.error = fmt::format("cannot open: {}{}", std::strerror(errno),
                                     errno == EACCES ? " (add the user to group video)" : "");
            continue;
        }
        if (drmVersionPtr v = drmGetVersion(fd)) {
            card.driver = v->name ? v->name : "";
            drmFreeVersion(v);
        }
        drmModeRes* res = drmModeGetResources(fd);
        if (!res) {
            card.error = "no display outputs (a render-only GPU)";
            ::close(fd);
            continue;
        }
        for (int i = 0; i < res->count_connectors; ++i) {
            drmModeConnector* c = drmModeGetConnector(fd, res->connectors[i]);
            if (!c) continue;
            const char* type = drmModeGetConnectorTypeName(c->connector_type);
            DrmConnectorInfo info{fmt::format("{}-{}", type ? type : "Unknown", c->connector_type_id),
                                  c->connection == DRM_MODE_CONNECTED, {}};
            for (int m = 0; m < c->count_modes; ++m) {
                const drmModeModeInfo& mode = c->modes[m];
                std::string text = fmt::format("{}x{}@{}", mode.hdisplay, mode.vdisplay, mode.vrefresh);
                if (mode.type & DRM_MODE_TYPE_PREFERRED) info.modes.insert(info.modes.begin(), text + " (preferred)");
                else if (std::find(info.modes.begin(), info.modes.end(), text) == info.modes.end())
                    info.modes.push_back(text);
            }
            card.connectors.push_back(std::move(info));
            drmModeFreeConnector(c);
        }
        drmModeFreeResources(res);
        ::close(fd);
    }
    return cards;
}

}  // namespace puddle::platform
