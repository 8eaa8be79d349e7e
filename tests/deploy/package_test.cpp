// The .deb CPack builds from this tree holds what a kiosk needs, at the paths systemd, udev and dpkg
// expect, with its library dependencies and the config marked as a conffile.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "support/test_support.hpp"

namespace puddle::test {
namespace {

TEST(Package, DebHoldsBinaryConfigPresetsUnitUdevRuleAndUser) {
    for (const char* tool : {"cpack", "dpkg-deb", "dpkg-shlibdeps"})
        if (run_command(std::string("command -v ") + tool).exit_code != 0)
            GTEST_SKIP() << tool << " is not installed (deploy/setup.sh installs it: cmake, dpkg-dev)";
    TempDir dir;
    const auto cpack =
        run_command("cd " + std::string(PUDDLE_BUILD_DIR) + " && cpack -G DEB -B " + dir.path().string());
    ASSERT_EQ(cpack.exit_code, 0) << cpack.output;
    const std::string& log = cpack.output;
    std::string deb;
    for (const auto& f : std::filesystem::directory_iterator(dir.path()))
        if (f.path().extension() == ".deb") deb = f.path().string();
    ASSERT_FALSE(deb.empty()) << log;
    EXPECT_NE(deb.find("puddle_"), std::string::npos) << deb;

    const std::string contents = run_command("dpkg-deb --contents " + deb).output;
    for (const char* path :
         {"./usr/bin/puddle", "./usr/lib/puddle/libpuddle-images.so", "./etc/puddle/puddle.toml",
          "./usr/share/puddle/presets/downpour.toml", "./usr/share/puddle/presets/still_night.toml",
          "./usr/lib/systemd/system/puddle.service", "./usr/lib/udev/rules.d/99-puddle-gpio.rules",
          "./usr/lib/sysusers.d/puddle.conf", "./usr/share/doc/puddle/README.md",
          "./usr/share/doc/puddle/docs/architecture.md", "./usr/share/man/man1/puddle.1.gz"})
        EXPECT_NE(contents.find(path), std::string::npos) << path << " missing from:\n" << contents;

    const std::string info = run_command("dpkg-deb --info " + deb).output;
    EXPECT_NE(info.find("Package: puddle"), std::string::npos) << info;
    EXPECT_NE(info.find("libgpiod"), std::string::npos) << "Depends from the linked libraries:\n" << info;
    EXPECT_NE(info.find("libegl1"), std::string::npos) << info;
    EXPECT_NE(info.find("libopenimageio"), std::string::npos) << "the image module's library:\n" << info;
    EXPECT_EQ(run_command("dpkg-deb --field " + deb + " Package").output, "puddle\n");
    const std::string conffiles =
        run_command("dpkg-deb --ctrl-tarfile " + deb + " | tar -xO ./conffiles").output;
    EXPECT_EQ(conffiles, "/etc/puddle/puddle.toml\n");
}

}  // namespace
}  // namespace puddle::test
