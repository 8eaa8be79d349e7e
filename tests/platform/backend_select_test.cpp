// Backend selection: the pure choose_backend() for every combination, and the KMS probe and factory on a
// machine without a usable card (CI has no /dev/dri), which must fail with a reason, not crash.

#include "platform/backend_select.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "platform/display.hpp"

namespace puddle::platform {
namespace {

const KmsProbe kCard{"/dev/dri/card1", "/dev/dri/card1 can modeset, connector HDMI-A-1 connected"};
const KmsProbe kNoCard{"", "no /dev/dri/card* devices"};

TEST(BackendSelect, NamesEveryBackend) {
    EXPECT_EQ(backend_name(BackendKind::Auto), "auto");
    EXPECT_EQ(backend_name(BackendKind::Headless), "headless");
    EXPECT_EQ(backend_name(BackendKind::Kms), "kms");
    EXPECT_EQ(backend_name(BackendKind::Window), "window");
}

// The table is the one list: every backend once, its name read back to it, a factory and a summary (the
// --help text and the manual page are made from them).
TEST(BackendSelect, TheTableNamesEachBackendOnceAndReadsItsNameBack) {
    std::vector<std::string_view> names;
    for (const BackendInfo& b : display_backends()) {
        EXPECT_EQ(backend_name(b.kind), b.name);
        EXPECT_EQ(backend_from_name(b.name), b.kind);
        EXPECT_NE(b.create, nullptr) << b.name;
        EXPECT_FALSE(b.summary.empty()) << b.name;
        EXPECT_EQ(std::count(names.begin(), names.end(), b.name), 0) << b.name;
        names.push_back(b.name);
    }
    EXPECT_EQ(names.size(), 3u);
    EXPECT_EQ(backend_from_name("auto"), BackendKind::Auto);
    EXPECT_FALSE(backend_from_name("Kms"));
    EXPECT_FALSE(backend_from_name(""));
}

TEST(BackendSelect, AutoPrefersKmsWhenACardIsUsable) {
    const BackendChoice without_x = choose_backend(BackendKind::Auto, kCard, nullptr);
    EXPECT_EQ(without_x.kind, BackendKind::Kms);
    EXPECT_EQ(without_x.reason, kCard.reason);
    EXPECT_EQ(without_x.fallbacks, std::vector<BackendKind>{BackendKind::Headless});

    const BackendChoice with_x = choose_backend(BackendKind::Auto, kCard, ":0");
    EXPECT_EQ(with_x.kind, BackendKind::Kms);
    EXPECT_EQ(with_x.fallbacks, (std::vector<BackendKind>{BackendKind::Window, BackendKind::Headless}));
}

TEST(BackendSelect, AutoUsesWindowWithoutCardWhenDisplayIsSet) {
    const BackendChoice choice = choose_backend(BackendKind::Auto, kNoCard, ":99");
    EXPECT_EQ(choice.kind, BackendKind::Window);
    EXPECT_EQ(choice.reason, "no /dev/dri/card* devices; DISPLAY=:99");
    EXPECT_EQ(choice.fallbacks, std::vector<BackendKind>{BackendKind::Headless});
}

TEST(BackendSelect, AutoUsesHeadlessWithoutCardOrDisplay) {
    for (const char* env : {static_cast<const char*>(nullptr), ""}) {
        const BackendChoice choice = choose_backend(BackendKind::Auto, kNoCard, env);
        EXPECT_EQ(choice.kind, BackendKind::Headless);
        EXPECT_EQ(choice.reason, "no /dev/dri/card* devices; DISPLAY not set");
        EXPECT_TRUE(choice.fallbacks.empty());
    }
}

TEST(BackendSelect, ExplicitRequestIsKeptWithoutFallback) {
    for (BackendKind kind : {BackendKind::Headless, BackendKind::Kms, BackendKind::Window}) {
        for (const KmsProbe* kms : {&kCard, &kNoCard}) {
            for (const char* env : {static_cast<const char*>(nullptr), ":0"}) {
                const BackendChoice choice = choose_backend(kind, *kms, env);
                EXPECT_EQ(choice.kind, kind) << backend_name(kind);
                EXPECT_EQ(choice.reason, "requested explicitly");
                EXPECT_TRUE(choice.fallbacks.empty()) << backend_name(kind);
            }
        }
    }
}

DisplayOptions kms_options(std::string card) {
    DisplayOptions options;
    options.backend = BackendKind::Kms;
    options.card = std::move(card);
    return options;
}

bool machine_has_dri() {
    return std::filesystem::exists("/dev/dri");
}

TEST(KmsProbe, ReportsWhyNoCardIsUsable) {
    if (machine_has_dri())
        GTEST_SKIP() << "this machine has /dev/dri; the no-card path cannot be checked here";
    const KmsProbe probe = probe_kms("");
    EXPECT_TRUE(probe.card.empty());
    EXPECT_EQ(probe.reason, "no /dev/dri/card* devices");
}

TEST(KmsProbe, NamedCardThatDoesNotExistIsNotUsable) {
    const KmsProbe probe = probe_kms("/dev/dri/card97");
    EXPECT_TRUE(probe.card.empty());
    EXPECT_NE(probe.reason.find("/dev/dri/card97"), std::string::npos) << probe.reason;
    EXPECT_NE(probe.reason.find("No such file or directory"), std::string::npos) << probe.reason;
}

TEST(KmsDisplay, WithoutACardFailsWithDisplayExitCode) {
    if (machine_has_dri())
        GTEST_SKIP() << "this machine has /dev/dri; the no-card path cannot be checked here";
    const auto display = create_kms_display(kms_options(""));
    ASSERT_FALSE(display.ok());
    EXPECT_EQ(display.error().code, ExitCode::Display);
    EXPECT_EQ(display.error().message, "kms: no card can modeset: no /dev/dri/card* devices");
}

TEST(KmsDisplay, NamedMissingCardNamesThePathAndCause) {
    const auto display = create_kms_display(kms_options("/dev/dri/card97"));
    ASSERT_FALSE(display.ok());
    EXPECT_EQ(display.error().code, ExitCode::Display);
    EXPECT_EQ(display.error().message, "kms: /dev/dri/card97: open: No such file or directory");
}

TEST(KmsDisplay, FileThatIsNotADrmDeviceIsRejected) {
    // /dev/null opens fine but is no DRM device: the factory must say so rather than crash.
    const auto display = create_kms_display(kms_options("/dev/null"));
    ASSERT_FALSE(display.ok());
    EXPECT_EQ(display.error().code, ExitCode::Display);
    EXPECT_EQ(display.error().message.rfind("kms: /dev/null: ", 0), 0u) << display.error().message;
    const KmsProbe probe = probe_kms("/dev/null");
    EXPECT_TRUE(probe.card.empty());
    EXPECT_EQ(probe.reason.rfind("/dev/null: ", 0), 0u) << probe.reason;
}

}  // namespace
}  // namespace puddle::platform
