#include "schedule/zone_watch.hpp"

#include <sys/stat.h>

#include <cstdlib>
#include <ctime>
#include <system_error>

namespace puddle::schedule {

ZoneWatch::ZoneWatch(std::filesystem::path system_zone) : system_zone_(std::move(system_zone)) {
    seen_ = look();
    zone_ = name_of(seen_);
    ::tzset();
}

ZoneWatch::Fingerprint ZoneWatch::look() const {
    Fingerprint f;
    if (const char* tz = std::getenv("TZ")) f.tz = tz;
    std::error_code ec;
    if (std::filesystem::is_symlink(system_zone_, ec))
        f.target = std::filesystem::read_symlink(system_zone_, ec);
    struct stat st {};
    if (::stat(system_zone_.c_str(), &st) == 0) {  // through the link: the zone file itself
        f.inode = static_cast<long long>(st.st_ino);
        f.size = static_cast<long long>(st.st_size);
        f.mtime_ns = static_cast<long long>(st.st_mtim.tv_sec) * 1'000'000'000LL + st.st_mtim.tv_nsec;
    }
    return f;
}

Zone ZoneWatch::name_of(const Fingerprint& f) const {
    if (f.tz) {
        std::string name = f.tz->empty() ? "UTC" : *f.tz;
        if (name.front() == ':') name.erase(0, 1);
        return {name, "TZ"};
    }
    if (f.inode < 0) return {"UTC", "no " + system_zone_.string()};
    // A link into the zoneinfo tree names the zone by its path below it
    // ("../usr/share/zoneinfo/Europe/Berlin").
    const std::string target = f.target;
    const auto at = target.find("zoneinfo/");
    if (at != std::string::npos) return {target.substr(at + 9), system_zone_.string()};
    return {target.empty() ? "the zone in that file" : target, system_zone_.string()};
}

std::optional<Zone> ZoneWatch::refresh() {
    const Fingerprint now = look();
    std::lock_guard lock(mutex_);
    if (now == seen_) return std::nullopt;
    seen_ = now;
    zone_ = name_of(now);
    ::tzset();  // glibc reads the zone file again when its inode or mtime changed, TZ when its value did
    return zone_;
}

Zone ZoneWatch::zone() const {
    std::lock_guard lock(mutex_);
    return zone_;
}

}  // namespace puddle::schedule
