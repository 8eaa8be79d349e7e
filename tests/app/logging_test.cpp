// Log lines (app/logging.hpp): under the journal each line carries its syslog priority and no colour; to a
// file or pipe, plain level names without escape codes.
#include "app/logging.hpp"

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "support/test_support.hpp"

namespace puddle::app {
namespace {

TEST(Logging, UnderTheJournalLinesCarryPrioritiesAndNoColour) {
    test::TempDir dir;
    const std::string path = (dir / "journal.txt").string();
    std::fflush(stderr);
    const int saved = ::dup(STDERR_FILENO);
    FILE* f = std::fopen(path.c_str(), "w");
    ::dup2(::fileno(f), STDERR_FILENO);
    struct stat st {};
    ::fstat(STDERR_FILENO, &st);
    test::ScopedEnv stream("JOURNAL_STREAM", std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino));
    const LogStyle style = detect_log_style();
    spdlog::drop("puddle");
    setup_logging(style);
    spdlog::info("started: headless");
    spdlog::warn("gpio: gpiochip0 line 17: busy");
    spdlog::error("config: a.toml:3: bad");
    spdlog::default_logger()->flush();
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    std::fclose(f);
    spdlog::drop("puddle");
    EXPECT_EQ(style, LogStyle::Journal);
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(),
              "<6>started: headless\n<4>gpio: gpiochip0 line 17: busy\n<3>config: a.toml:3: bad\n");
}

TEST(Logging, AFileOrPipeGetsPlainLevelsWithoutEscapeCodes) {
    ::unsetenv("JOURNAL_STREAM");
    test::TempDir dir;
    const std::string path = (dir / "log.txt").string();
    std::fflush(stderr);
    const int saved = ::dup(STDERR_FILENO);
    FILE* f = std::fopen(path.c_str(), "w");
    ::dup2(::fileno(f), STDERR_FILENO);
    const LogStyle style = detect_log_style();
    spdlog::drop("puddle");
    setup_logging(style);
    spdlog::warn("something");
    spdlog::default_logger()->flush();
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    std::fclose(f);
    spdlog::drop("puddle");
    EXPECT_EQ(style, LogStyle::Plain);
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "warning: something\n");
}

// Issue 33, item 10: a command payload of invalid UTF-8 was clean in the MQTT reply but written raw into
// the log (and so into the journal). Every line is valid UTF-8, in every style; valid text is untouched.
TEST(Logging, EveryLineIsValidUtf8WhateverItQuotes) {
    for (const char* journal : {"", "journal"}) {
        SCOPED_TRACE(*journal ? "journal" : "plain");
        test::TempDir dir;
        const std::string path = (dir / "log.txt").string();
        std::fflush(stderr);
        const int saved = ::dup(STDERR_FILENO);
        FILE* f = std::fopen(path.c_str(), "w");
        ::dup2(::fileno(f), STDERR_FILENO);
        struct stat st {};
        ::fstat(STDERR_FILENO, &st);
        ::unsetenv("JOURNAL_STREAM");
        if (*journal)
            ::setenv("JOURNAL_STREAM", (std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino)).c_str(),
                     1);
        spdlog::drop("puddle");
        setup_logging(detect_log_style());
        spdlog::warn("remote: puddle/a/command: unknown command '{}'", "\xff\xfenext\xc0\xaf");
        spdlog::info(
            "sensor: SoC temperature 51 \xc2\xb0"
            "C");
        spdlog::default_logger()->flush();
        ::dup2(saved, STDERR_FILENO);
        ::close(saved);
        std::fclose(f);
        spdlog::drop("puddle");
        ::unsetenv("JOURNAL_STREAM");
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        const std::string r = "\xef\xbf\xbd";
        const std::string warn = *journal ? "<4>" : "warning: ", info = *journal ? "<6>" : "info: ";
        EXPECT_EQ(text.str(), warn + "remote: puddle/a/command: unknown command '" + r + r + "next" + r + r +
                                  "'\n" + info +
                                  "sensor: SoC temperature 51 \xc2\xb0"
                                  "C\n");
    }
}

}  // namespace
}  // namespace puddle::app
