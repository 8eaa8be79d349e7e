// util/recurring_fault.hpp: said in full once, then summarised at doubling intervals, said in full again
// after it ended.
#include "util/recurring_fault.hpp"

#include <gtest/gtest.h>

namespace puddle {
namespace {

using Say = RecurringFault::Say;

TEST(RecurringFault, OnceInFullThenSummariesAtDoublingIntervalsWithTheCount) {
    RecurringFault f;
    EXPECT_FALSE(f.active());
    const auto first = f.occurred(100, 1000);
    EXPECT_EQ(first.say, Say::Full);
    EXPECT_EQ(first.total, 1u);
    // Every 2 s for an hour: a warning every 2 s before; now the first line and a few summaries.
    int full = 0, summaries = 0;
    std::uint64_t counted = 1;
    for (double t = 102; t <= 100 + 3600; t += 2) {
        const auto r = f.occurred(t, 1000 + t - 100);
        full += r.say == Say::Full;
        if (r.say == Say::Summary) {
            ++summaries;
            counted += r.since_said;
            EXPECT_EQ(r.total, counted) << "a summary counts every occurrence since the last line";
        }
    }
    EXPECT_EQ(full, 0);
    EXPECT_EQ(summaries, 5) << "at 60, 180, 420, 900 and 1860 s";  // 60 s doubling
    EXPECT_TRUE(f.active());
    EXPECT_EQ(f.last_wall(), 1000 + 3600);
    EXPECT_EQ(f.clear(), 1801u);
    EXPECT_FALSE(f.active());
    EXPECT_EQ(f.clear(), 0u);
    EXPECT_EQ(f.occurred(9000, 9000).say, Say::Full) << "after it ended, said in full again";
}

TEST(RecurringFault, TheIntervalStopsGrowingAtTheMaximum) {
    RecurringFault f;
    f.occurred(0, 0);
    int summaries = 0;
    for (double t = 10; t <= 3 * 24 * 3600.0; t += 10) summaries += f.occurred(t, t).say == Say::Summary;
    // 60 s doubling to 1920 s (six summaries by 3780 s), then one an hour for the rest of the three days.
    EXPECT_EQ(summaries, 6 + (3 * 24 * 3600 - 3780) / 3600);
}

}  // namespace
}  // namespace puddle
