#include "schedule/time_zone.hpp"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace puddle::schedule {
namespace {

// A POSIX rule starts with a zone name (three or more letters, or "<...>") followed by its UTC offset.
bool is_posix_rule(std::string_view tz) {
    std::size_t i = 0;
    if (!tz.empty() && tz[0] == '<') {
        i = tz.find('>');
        if (i == std::string_view::npos) return false;
        ++i;
    } else {
        while (i < tz.size() && std::isalpha(static_cast<unsigned char>(tz[i]))) ++i;
        if (i < 3) return false;
    }
    return i < tz.size() && (std::isdigit(static_cast<unsigned char>(tz[i])) || tz[i] == '+' || tz[i] == '-');
}

}  // namespace

std::optional<std::string> time_zone_problem(const char* tz, std::string_view zoneinfo_dir) {
    if (tz == nullptr || *tz == '\0') return std::nullopt;
    std::string_view name = tz;
    if (name.front() == ':')
        name.remove_prefix(1);
    else if (is_posix_rule(name))
        return std::nullopt;
    const std::filesystem::path file = !name.empty() && name.front() == '/'
                                           ? std::filesystem::path(name)
                                           : std::filesystem::path(zoneinfo_dir) / std::string(name);
    std::error_code ec;
    if (!name.empty() && std::filesystem::is_regular_file(file, ec)) return std::nullopt;
    return "TZ='" + std::string(tz) + "' is no time zone (no file " + file.string() +
           "), so local time is UTC: set a zone name such as Europe/Berlin (timedatectl list-timezones), "
           "or unset TZ to use /etc/localtime";
}

std::optional<std::string> time_zone_problem() {
    const char* dir = std::getenv("TZDIR");
    return time_zone_problem(std::getenv("TZ"), dir && *dir ? dir : "/usr/share/zoneinfo");
}

}  // namespace puddle::schedule
