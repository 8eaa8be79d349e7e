// TLS and a password against a real Mosquitto: a CA and a server certificate made by
// openssl at test time, a broker config and password file written by the test.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <thread>

#include "support/mosquitto_broker.hpp"
#include "support/running_puddle.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

// Mosquitto started as root drops to the user `mosquitto`, which cannot read the test's key: stay this user.
std::string user_name() {
    const passwd* pw = getpwuid(getuid());
    return pw ? pw->pw_name : "root";
}

class RemoteTls : public ::testing::Test {
protected:
    void SetUp() override {
        if (!mosquitto_available()) GTEST_SKIP() << no_mosquitto;
        if (access("/usr/bin/openssl", X_OK) != 0 || access("/usr/bin/mosquitto_passwd", X_OK) != 0)
            GTEST_SKIP()
                << "openssl or mosquitto_passwd is not installed (apt-get install openssl mosquitto)";
        dir.write("san.ext", "subjectAltName=DNS:localhost\n");
        const auto made = run_command(fmt::format(
            "cd {} && openssl req -x509 -newkey rsa:2048 -nodes -keyout ca.key -out ca.crt -days 1 "
            "-subj /CN=puddle-test-ca && openssl req -newkey rsa:2048 -nodes -keyout server.key -out "
            "server.csr "
            "-subj /CN=localhost && openssl x509 -req -in server.csr -CA ca.crt -CAkey ca.key "
            "-CAcreateserial "
            "-out server.crt -days 1 -extfile san.ext && mosquitto_passwd -b -c broker.passwd screen s3cret",
            dir.path().string()));
        ASSERT_EQ(made.exit_code, 0) << made.output;
        port = free_port();
        broker = std::make_unique<MosquittoBroker>(
            port,
            fmt::format("listener {} 127.0.0.1\ncafile {}\ncertfile {}\nkeyfile {}\nallow_anonymous false\n"
                        "password_file {}\nuser {}\n",
                        port, (dir / "ca.crt").string(), (dir / "server.crt").string(),
                        (dir / "server.key").string(), (dir / "broker.passwd").string(), user_name()));
        ASSERT_TRUE(broker->running()) << broker->log();
    }
    void write_config(const std::string& password) {
        const std::string file = dir.write("password", password + "\n");
        chmod(file.c_str(), 0600);
        dir.write(
            "puddle.toml",
            fmt::format(
                "[remote]\nenabled = true\nport = {}\nprefix = \"puddle/tls\"\nclient_id = \"puddle-tls\"\n"
                "tls_ca = \"{}\"\nusername = \"screen\"\npassword_file = \"{}\"\n",
                port, (dir / "ca.crt").string(), file));
    }
    std::vector<std::string> args() const {
        return {"--config",  (dir / "puddle.toml").string(),
                "--state",   (dir / "state.toml").string(),
                "-b",        "headless",
                "--size",    "160x90",
                "--frames",  "0",
                "--fps-cap", "30"};
    }

    TempDir dir;
    int port = 0;
    std::unique_ptr<MosquittoBroker> broker;
};

TEST_F(RemoteTls, TlsAndPasswordConnectAndASetApplies) {
    write_config("s3cret");
    MqttTestClient client(
        {.port = port, .ca_file = (dir / "ca.crt").string(), .username = "screen", .password = "s3cret"});
    ASSERT_TRUE(client.connected());
    client.subscribe("puddle/tls/#");
    Running puddle(args(), dir / "puddle.log");
    ASSERT_TRUE(client.wait_for(
        "puddle/tls/availability", [](auto& p) { return p == "online"; }, 60))
        << puddle.log();
    client.publish("puddle/tls/set/look.vignette", "1.1");
    EXPECT_TRUE(client.wait_for("puddle/tls/state/look.vignette", [](auto& p) { return p == "1.1"; }))
        << puddle.log();
    EXPECT_EQ(puddle.stop(), 0);
}

TEST_F(RemoteTls, AWrongPasswordIsOneWarningAndTheDisplayRuns) {
    write_config("wrong");
    auto a = args();
    a.insert(a.end(), {"--stats", "1"});
    Running puddle(a, dir / "puddle.log");
    ASSERT_TRUE(puddle.wait_for("stats:", 3)) << puddle.log();
    EXPECT_EQ(puddle.count("the broker refused the connection"), 1) << puddle.log();
    EXPECT_EQ(puddle.count("warning: remote"), 1) << puddle.log();
    EXPECT_EQ(puddle.stop(), 0);
}

TEST_F(RemoteTls, AWorldReadablePasswordFileIsRefusedAtStartUp) {
    write_config("s3cret");
    chmod((dir / "password").c_str(), 0644);
    const auto r = run_puddle(
        fmt::format("--config {} -b headless --size 64x64 --frames 1", (dir / "puddle.toml").string()));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("remote: remote.password_file = " + (dir / "password").string() +
                            ": others may read it; refused (chmod 600"),
              std::string::npos)
        << r.output;
}

}  // namespace
}  // namespace puddle::test
