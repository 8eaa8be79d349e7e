// schedule/time_zone.hpp: a TZ glibc cannot resolve (and silently takes as UTC) is named; the forms it
// resolves are not. The zone files come from a folder the test makes, so the result does not depend on
// the machine's tzdata.
#include "schedule/time_zone.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/test_support.hpp"

namespace puddle::schedule {
namespace {

class TimeZoneProblem : public ::testing::Test {
protected:
    void SetUp() override {
        std::filesystem::create_directories(dir_.path() / "Europe");
        std::ofstream(dir_.path() / "Europe" / "Berlin") << "TZif";
    }
    std::optional<std::string> problem(const char* tz) { return time_zone_problem(tz, dir_.path().string()); }
    test::TempDir dir_;
};

TEST_F(TimeZoneProblem, UnsetEmptyAndKnownZonesAreFine) {
    EXPECT_EQ(problem(nullptr), std::nullopt) << "unset: /etc/localtime";
    EXPECT_EQ(problem(""), std::nullopt) << "empty: UTC on purpose";
    EXPECT_EQ(problem("Europe/Berlin"), std::nullopt);
    EXPECT_EQ(problem(":Europe/Berlin"), std::nullopt);
    const std::string absolute = (dir_.path() / "Europe" / "Berlin").string();
    EXPECT_EQ(problem(absolute.c_str()), std::nullopt);
}

TEST_F(TimeZoneProblem, PosixRulesNeedNoFile) {
    EXPECT_EQ(problem("UTC0"), std::nullopt);
    EXPECT_EQ(problem("EST5EDT"), std::nullopt);
    EXPECT_EQ(problem("CET-1CEST,M3.5.0,M10.5.0/3"), std::nullopt);
    EXPECT_EQ(problem("<+03>-3"), std::nullopt);
}

TEST_F(TimeZoneProblem, AMisspelledZoneIsNamedWithWhatLocalTimeBecomes) {
    const auto p = problem("Europe/Berln");
    ASSERT_TRUE(p.has_value());
    EXPECT_NE(p->find("TZ='Europe/Berln'"), std::string::npos) << *p;
    EXPECT_NE(p->find((dir_.path() / "Europe" / "Berln").string()), std::string::npos) << *p;
    EXPECT_NE(p->find("local time is UTC"), std::string::npos) << *p;
    EXPECT_TRUE(problem("Foo").has_value()) << "too short for a rule, and no file";
    EXPECT_TRUE(problem(":Nowhere/Town").has_value());
    EXPECT_TRUE(problem("Europe").has_value()) << "a folder is not a zone";
    EXPECT_TRUE(problem("/no/such/file").has_value());
}

}  // namespace
}  // namespace puddle::schedule
