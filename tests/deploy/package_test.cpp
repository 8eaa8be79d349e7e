// The .deb CPack builds from this tree holds what a kiosk needs, at the paths systemd, udev and dpkg
// expect, with its library dependencies and the config marked as a conffile.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "support/test_support.hpp"

namespace puddle::test {
namespace {

std::string run(const std::string& cmd, int* status = nullptr) {
    FILE* p = popen((cmd + " 2>&1").c_str(), "r");
    std::string out;
    char buf[1024];
    while (p && std::fgets(buf, sizeof buf, p)) out += buf;
    const int s = p ? pclose(p) : -1;
    if (status) *status = s;
    return out;
}

TEST(Package, DebHoldsBinaryConfigPresetsUnitUdevRuleAndUser) {
    for (const char* tool : {"cpack", "dpkg-deb", "dpkg-shlibdeps"})
        if (run(std::string("command -v ") + tool).empty())
            GTEST_SKIP() << tool << " is not installed (deploy/setup.sh installs it: cmake, dpkg-dev)";
    TempDir dir;
    int status = 0;
    const std::string log = run("cd " + std::string(PUDDLE_BUILD_DIR) + " && cpack -G DEB -B " + dir.path().string(), &status);
    ASSERT_EQ(status, 0) << log;
    std::string deb;
    for (const auto& f : std::filesystem::directory_iterator(dir.path()))
        if (f.path().extension() == ".deb") deb = f.path().string();
    ASSERT_FALSE(deb.empty()) << log;
    EXPECT_NE(deb.find("puddle_"), std::string::npos) << deb;

    const std::string contents = run("dpkg-deb --contents " + deb);
    for (const char* path : {"./usr/bin/puddle", "./etc/puddle/puddle.toml", "./usr/share/puddle/presets/downpour.toml",
                             "./usr/share/puddle/presets/still_night.toml", "./usr/lib/systemd/system/puddle.service",
                             "./usr/lib/udev/rules.d/99-puddle-gpio.rules", "./usr/lib/sysusers.d/puddle.conf",
                             "./usr/share/doc/puddle/README.md"})
        EXPECT_NE(contents.find(path), std::string::npos) << path << " missing from:\n" << contents;

    const std::string info = run("dpkg-deb --info " + deb);
    EXPECT_NE(info.find("Package: puddle"), std::string::npos) << info;
    EXPECT_NE(info.find("libgpiod"), std::string::npos) << "Depends from the linked libraries:\n" << info;
    EXPECT_NE(info.find("libegl1"), std::string::npos) << info;
    EXPECT_EQ(run("dpkg-deb --field " + deb + " Package"), "puddle\n");
    const std::string conffiles = run("dpkg-deb --ctrl-tarfile " + deb + " | tar -xO ./conffiles");
    EXPECT_EQ(conffiles, "/etc/puddle/puddle.toml\n");
}

}  // namespace
}  // namespace puddle::test
