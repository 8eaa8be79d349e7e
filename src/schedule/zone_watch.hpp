#pragma once
// Which time zone local time is in, and a change of it while Puddle runs (timedatectl set-timezone
// re-points /etc/localtime).
//
// The C library reads the zone once: localtime_r never looks again, so a changed /etc/localtime was
// ignored until a restart. tzset() reads it again when the file changed (glibc compares its inode and
// mtime; time/tzfile.c), so the watch compares the zone's source and calls tzset() when it moved.
// Sources, as tzset(3): TZ when set (a zone name, a POSIX rule or a file), else /etc/localtime (usually a
// link into /usr/share/zoneinfo, whose path names the zone), else UTC.

#include <filesystem>
#include <mutex>
#include <optional>
#include <string>

namespace puddle::schedule {

struct Zone {
    std::string name;    // "Europe/Berlin", a POSIX rule such as "CET-1CEST,M3.5.0,M10.5.0/3", or "UTC"
    std::string source;  // "TZ", the system zone file's path, or "no /etc/localtime"
    std::string describe() const { return name + " (" + (source == "TZ" ? "from TZ" : source) + ")"; }
    bool operator==(const Zone&) const = default;
};

// Thread-safe: the frame thread refreshes at a reload, a worker thread every minute.
class ZoneWatch {
public:
    // Reads the zone now (calls tzset()). `system_zone` is where the system's zone is: the C library reads
    // /etc/localtime whatever is passed, so another path serves only tests of the change detection.
    explicit ZoneWatch(std::filesystem::path system_zone = "/etc/localtime");
    ZoneWatch(const ZoneWatch&) = delete;
    ZoneWatch& operator=(const ZoneWatch&) = delete;

    // Looks at the zone's source (TZ; the system zone's link target, inode, size and mtime: a getenv, a
    // readlink and a stat) and, when it changed since the last look, calls tzset() so that local time
    // follows, and returns the zone now in force. Nothing when unchanged.
    std::optional<Zone> refresh();
    Zone zone() const;

private:
    struct Fingerprint {
        std::optional<std::string> tz;  // TZ's value; none when unset
        std::string target;             // the system zone link's target, empty when it is no link
        long long inode = -1, size = -1, mtime_ns = -1;
        bool operator==(const Fingerprint&) const = default;
    };
    Fingerprint look() const;
    Zone name_of(const Fingerprint& f) const;

    std::filesystem::path system_zone_;
    mutable std::mutex mutex_;
    Fingerprint seen_;
    Zone zone_;
};

}  // namespace puddle::schedule
