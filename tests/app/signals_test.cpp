// Stop and reload signals as a file descriptor (app/signals.hpp): SIGTERM and SIGINT are a stop that
// stays, SIGHUP a reload taken once and never a stop, and the thread's signal mask is given back. Each
// test consumes every signal it raises before the StopSignals dies (an unblocked SIGHUP or SIGTERM would
// end the test process).
#include "app/signals.hpp"

#include <gtest/gtest.h>
#include <pthread.h>

#include <csignal>

namespace puddle::app {
namespace {

bool blocked(int signal) {
    sigset_t now;
    pthread_sigmask(SIG_SETMASK, nullptr, &now);
    return sigismember(&now, signal) == 1;
}

TEST(StopSignals, NothingRaisedIsNeitherAStopNorAReload) {
    StopSignals signals;
    EXPECT_FALSE(signals.requested());
    EXPECT_FALSE(signals.take_reload());
    EXPECT_EQ(signals.last_signal(), 0);
}

TEST(StopSignals, SighupIsAReloadTakenOnceAndNotAStop) {
    StopSignals signals;
    ASSERT_EQ(raise(SIGHUP), 0);
    EXPECT_FALSE(signals.requested());
    EXPECT_TRUE(signals.take_reload());
    EXPECT_FALSE(signals.take_reload()) << "taken";
    EXPECT_FALSE(signals.requested());
}

TEST(StopSignals, SigtermAndSigintAreAStopThatStays) {
    for (const int signal : {SIGTERM, SIGINT}) {
        StopSignals signals;
        ASSERT_EQ(raise(signal), 0);
        EXPECT_TRUE(signals.requested()) << signal;
        EXPECT_EQ(signals.last_signal(), signal);
        EXPECT_TRUE(signals.requested()) << "still stopping on the next frame";
    }
}

// A reload that arrived before the stop is not lost.
TEST(StopSignals, AReloadBeforeAStopIsKept) {
    StopSignals signals;
    ASSERT_EQ(raise(SIGHUP), 0);
    ASSERT_EQ(raise(SIGTERM), 0);
    EXPECT_TRUE(signals.requested());
    EXPECT_EQ(signals.last_signal(), SIGTERM);
    EXPECT_TRUE(signals.take_reload());
}

TEST(StopSignals, TheThreadsSignalMaskIsGivenBack) {
    ASSERT_FALSE(blocked(SIGTERM));
    {
        StopSignals signals;
        EXPECT_TRUE(blocked(SIGTERM));
        EXPECT_TRUE(blocked(SIGINT));
        EXPECT_TRUE(blocked(SIGHUP));
    }
    EXPECT_FALSE(blocked(SIGTERM));
    EXPECT_FALSE(blocked(SIGHUP));
}

}  // namespace
}  // namespace puddle::app
