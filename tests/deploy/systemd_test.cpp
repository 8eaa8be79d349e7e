// The systemd unit and sysusers file in deploy/, checked by systemd's own tools when they are installed:
// the unit verifies against the binary just built, and sysusers makes the user in its device groups.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/test_support.hpp"

namespace puddle::test {
namespace {

TEST(Deploy, SystemdAcceptsTheUnit) {
    if (std::system("command -v systemd-analyze >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "systemd-analyze is not installed";
    TempDir dir;
    std::ifstream in(std::string(PUDDLE_SOURCE_DIR) + "/deploy/puddle.service");
    std::stringstream unit;
    unit << in.rdbuf();
    std::string text = unit.str();
    // The unit names the installed binary; verify it against the one just built.
    const auto at = text.find("/usr/bin/puddle");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, std::string("/usr/bin/puddle").size(), PUDDLE_BINARY);
    for (const char* key : {"Type=notify", "WatchdogSec=", "Restart=always", "StateDirectory=puddle",
                            "ConfigurationDirectory=puddle", "CacheDirectory=puddle",
                            "Environment=MESA_SHADER_CACHE_DIR=%C/puddle", "NoNewPrivileges=yes",
                            "ProtectSystem=strict", "ProtectHome=yes", "PrivateTmp=yes",
                            "SupplementaryGroups=video render input gpio", "TTYPath=/dev/tty"})
        EXPECT_NE(text.find(key), std::string::npos) << key;
    const std::string path = dir.write("puddle.service", text);
    const auto verify = run_command("systemd-analyze verify " + path);
    EXPECT_EQ(verify.exit_code, 0) << verify.output;
    EXPECT_EQ(verify.output.find("puddle.service"), std::string::npos) << "no complaint about the unit:\n"
                                                                       << verify.output;
}

TEST(Deploy, SysusersCreatesTheUserInItsGroups) {
    if (std::system("command -v systemd-sysusers >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "systemd-sysusers is not installed";
    TempDir root;
    std::filesystem::create_directories(root / "etc");
    // A root with the groups a Debian system has.
    std::ofstream(root / "etc" / "group") << "root:x:0:\nvideo:x:44:\ninput:x:105:\nrender:x:106:\n";
    std::ofstream(root / "etc" / "passwd") << "root:x:0:0:root:/root:/bin/sh\n";
    const std::string cmd = "systemd-sysusers --root=" + root.path().string() + " " + PUDDLE_SOURCE_DIR +
                            "/deploy/puddle.sysusers 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::ifstream passwd(root / "etc" / "passwd"), group(root / "etc" / "group");
    std::stringstream p, g;
    p << passwd.rdbuf();
    g << group.rdbuf();
    EXPECT_NE(p.str().find("puddle:x:"), std::string::npos) << p.str();
    EXPECT_NE(g.str().find("gpio:x:"), std::string::npos) << g.str();
    for (const char* grp : {"video:x:44:puddle", "input:x:105:puddle", "render:x:106:puddle"})
        EXPECT_NE(g.str().find(grp), std::string::npos) << grp << "\n" << g.str();
}

}  // namespace
}  // namespace puddle::test
