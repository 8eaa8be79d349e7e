#include "remote/remote_settings.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <fstream>

namespace puddle::remote {

using params::ParamId;

namespace {

// "" when there is none.
std::string host_name() {
    std::array<char, 256> host{};
    if (gethostname(host.data(), host.size() - 1) == 0) return host.data();
    return "";
}

}  // namespace

std::string device_id(const std::string& machine_id_file) {
    std::ifstream in(machine_id_file);
    std::string line;
    if (in && std::getline(in, line) && line.size() >= 12) return line.substr(0, 12);
    if (std::string host = host_name(); !host.empty()) return host;
    return "unknown";
}

Result<std::string> read_password_file(const std::string& path) {
    struct stat st {};
    if (stat(path.c_str(), &st) != 0)
        return make_error(ExitCode::Config, "remote: remote.password_file = {}: cannot read it", path);
    if (st.st_mode & (S_IROTH | S_IWOTH))
        return make_error(ExitCode::Config,
                          "remote: remote.password_file = {}: others may read it; refused (chmod 600 {})",
                          path, path);
    std::ifstream in(path);
    std::string line;
    if (!in || !std::getline(in, line))
        return make_error(ExitCode::Config, "remote: remote.password_file = {}: cannot read it", path);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return line;
}

Result<RemoteSettings> remote_settings(const params::Params& p) {
    RemoteSettings s;
    s.enabled = p.get<ParamId::remote_enabled>();
    s.host = p.get<ParamId::remote_host>();
    s.port = p.get<ParamId::remote_port>();
    s.device_id = device_id();
    s.client_id = p.get<ParamId::remote_client_id>();
    s.screen_name = s.client_id.starts_with("puddle-") ? s.client_id.substr(7) : s.client_id;
    if (s.client_id.empty()) {
        s.client_id = "puddle-" + s.device_id;
        s.screen_name = host_name();
        if (s.screen_name.empty()) s.screen_name = s.device_id;
    }
    s.prefix = p.get<ParamId::remote_prefix>();
    if (s.prefix.empty()) s.prefix = "puddle/" + s.device_id;
    s.fleet_prefix = p.get<ParamId::remote_fleet_prefix>();
    for (const auto& [name, prefix] :
         {std::pair{"remote.prefix", &s.prefix}, {"remote.fleet_prefix", &s.fleet_prefix}})
        if (prefix->find_first_of("+#") != std::string::npos || prefix->ends_with('/'))
            return make_error(
                ExitCode::Config,
                "remote: {} = \"{}\": a topic prefix has no MQTT wildcards (+ #) and no trailing '/'", name,
                *prefix);
    s.keepalive_s = p.get<ParamId::remote_keepalive>();
    s.tls_ca = p.get<ParamId::remote_tls_ca>();
    s.tls_cert = p.get<ParamId::remote_tls_cert>();
    s.tls_key = p.get<ParamId::remote_tls_key>();
    if (s.tls_cert.empty() != s.tls_key.empty())
        return make_error(ExitCode::Config,
                          "remote: remote.tls_cert and remote.tls_key go together; one is empty");
    for (const auto& [name, file] : {std::pair{"remote.tls_ca", &s.tls_ca},
                                     {"remote.tls_cert", &s.tls_cert},
                                     {"remote.tls_key", &s.tls_key}})
        if (!file->empty() && access(file->c_str(), R_OK) != 0)
            return make_error(ExitCode::Config, "remote: {} = {}: cannot read it", name, *file);
    s.username = p.get<ParamId::remote_username>();
    if (const std::string& file = p.get<ParamId::remote_password_file>(); !file.empty()) {
        auto password = read_password_file(file);
        if (!password) return password.error();
        s.password = std::move(*password);
    }
    s.writable = WritablePatterns(p.get<ParamId::remote_writable>());
    s.screenshot_width = p.get<ParamId::remote_screenshot_width>();
    s.health_interval_s = p.get<ParamId::remote_health_interval>();
    return s;
}

}  // namespace puddle::remote
