#pragma once
// The [remote] section as the MQTT client uses it: read once at start-up from the effective parameters
// (remote.* in params.def), with the defaults that depend on the machine filled in and the password read
// from its file.
//
// Topics under the prefix P (docs/remote-control.md has the table):
//   in:  P/set/<parameter>  P/preset/set  P/command   (the same three under the fleet prefix; commands,
//        so a retained message there is ignored: remote_request.hpp)
//        homeassistant/status ("online": discovery is published again; may be retained)
//   out: P/availability  P/state  P/state/<parameter>  P/preset  P/health  P/screenshot  P/error

#include <string>

#include "params/param_store.hpp"
#include "remote/writable_patterns.hpp"
#include "util/result.hpp"

namespace puddle::remote {

struct RemoteSettings {
    bool enabled = false;
    std::string host;
    int port = 1883;
    std::string device_id;  // the first 12 characters of /etc/machine-id, or the host name
    std::string client_id;
    // What people call this screen (Home Assistant's device "Puddle <screen name>"): remote.client_id
    // when set (less a leading "puddle-"), else the host name, else the device id.
    std::string screen_name;
    std::string prefix;        // "puddle/<device id>", no trailing '/'
    std::string fleet_prefix;  // "" for none
    int keepalive_s = 30;
    std::string tls_ca, tls_cert, tls_key;  // tls_ca set: TLS
    std::string username;
    std::string password;  // from remote.password_file; never from the config itself
    WritablePatterns writable;
    int screenshot_width = 640;
    double health_interval_s = 5.0;
};

// The machine's id for topic and client names: the first 12 characters of `machine_id_file`'s first line
// (systemd's /etc/machine-id), else the host name, else "unknown".
std::string device_id(const std::string& machine_id_file = "/etc/machine-id");

// Errors (exit code 2, one line naming the parameter and the file): a password file that cannot be read
// or that others may read ("chmod 600"), a TLS client certificate without its key (or the reverse), a
// TLS file that cannot be read, a prefix with MQTT wildcards (+ #) or a trailing '/'.
Result<RemoteSettings> remote_settings(const params::Params& params);

// Reads the first line of a password file; refused when its mode lets others read it.
Result<std::string> read_password_file(const std::string& path);

}  // namespace puddle::remote
