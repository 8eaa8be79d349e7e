// The time zone in force and a change of it while running (schedule/zone_watch.hpp): the system zone's
// link target names the zone and a re-pointed link is seen (the path is injected: /etc/localtime needs
// root), and a changed TZ is in force for localtime_r after a refresh (the C library reads the zone once
// and keeps it until tzset()).
#include "schedule/zone_watch.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>

#include "schedule/tz_guard.hpp"
#include "support/test_support.hpp"

namespace puddle::schedule {
namespace {

namespace fs = std::filesystem;

// TZ unset for one test (the system zone then applies), restored after.
class NoTz {
public:
    NoTz() {
        if (const char* old = std::getenv("TZ")) old_ = old;
        ::unsetenv("TZ");
    }
    ~NoTz() {
        if (old_) ::setenv("TZ", old_->c_str(), 1);
        ::tzset();
    }
    NoTz(const NoTz&) = delete;
    NoTz& operator=(const NoTz&) = delete;

private:
    std::optional<std::string> old_;
};

long utc_offset_at(std::time_t t) {
    tm l{};
    localtime_r(&t, &l);
    return l.tm_gmtoff;
}

const fs::path zoneinfo = "/usr/share/zoneinfo";

TEST(ZoneWatch, TheSystemZonesLinkNamesTheZoneAndARepointedLinkIsSeen) {
    if (!fs::exists(zoneinfo / "Europe/Berlin") || !fs::exists(zoneinfo / "America/New_York"))
        GTEST_SKIP() << "no tzdata under " << zoneinfo;
    NoTz no_tz;
    test::TempDir dir;
    const fs::path link = dir / "localtime";
    fs::create_symlink(zoneinfo / "Europe/Berlin", link);
    ZoneWatch watch(link);
    EXPECT_EQ(watch.zone(), (Zone{"Europe/Berlin", link.string()}));
    EXPECT_EQ(watch.zone().describe(), "Europe/Berlin (" + link.string() + ")");
    EXPECT_FALSE(watch.refresh()) << "nothing changed";
    // timedatectl set-timezone: the link is replaced by one to the new zone.
    fs::remove(link);
    fs::create_symlink(zoneinfo / "America/New_York", link);
    const auto changed = watch.refresh();
    ASSERT_TRUE(changed);
    EXPECT_EQ(*changed, (Zone{"America/New_York", link.string()}));
    EXPECT_EQ(watch.zone(), *changed);
    EXPECT_FALSE(watch.refresh()) << "seen once";
    fs::remove(link);
    const auto gone = watch.refresh();
    ASSERT_TRUE(gone);
    EXPECT_EQ(gone->name, "UTC") << "glibc's zone without /etc/localtime";
}

TEST(ZoneWatch, AChangedTzIsInForceAfterARefresh) {
    if (!fs::exists(zoneinfo / "Europe/Berlin") || !fs::exists(zoneinfo / "America/New_York"))
        GTEST_SKIP() << "no tzdata under " << zoneinfo;
    test::TzGuard tz("Europe/Berlin");
    const std::time_t june = 1'780'000'000;  // 2026-05-28, summer time on both sides of the Atlantic
    ZoneWatch watch(zoneinfo / "none");
    EXPECT_EQ(watch.zone(), (Zone{"Europe/Berlin", "TZ"}));
    EXPECT_EQ(utc_offset_at(june), 2 * 3600);
    ::setenv("TZ", "America/New_York", 1);  // no tzset(): the watch must make it apply
    const auto changed = watch.refresh();
    ASSERT_TRUE(changed);
    EXPECT_EQ(*changed, (Zone{"America/New_York", "TZ"}));
    EXPECT_EQ(utc_offset_at(june), -4 * 3600) << "local time follows the new zone";
}

}  // namespace
}  // namespace puddle::schedule
