#include "remote/remote_request.hpp"

#include <cmath>
#include <cstdlib>
#include <iterator>

#include "util/safe_quote.hpp"

namespace puddle::remote {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\n' || s.front() == '\r'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\n' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

// The rest of `topic` after "<prefix>/", under either prefix; npos when under neither.
std::string_view after_prefix(const RemoteSettings& s, std::string_view topic) {
    for (const std::string* prefix : {&s.prefix, &s.fleet_prefix}) {
        if (prefix->empty()) continue;
        if (topic.size() > prefix->size() && topic.starts_with(*prefix) && topic[prefix->size()] == '/')
            return topic.substr(prefix->size() + 1);
    }
    return {};
}

Result<Request> set_param(const RemoteSettings& s, std::string_view topic, std::string_view name,
                          std::string_view payload) {
    const params::ParamDecl* d = params::find_param(name);
    if (!d)
        return make_error(ExitCode::Config, "remote: {}: unknown parameter '{}' (did you mean '{}'?)",
                          safe_quote(topic), safe_quote(name), params::nearest_param_name(name));
    if (!s.writable.allows(*d))
        return make_error(ExitCode::Config, "remote: {}: {} cannot be set remotely ({})", safe_quote(topic),
                          d->name,
                          WritablePatterns::device_setting(d->name) ? "a setting of the device itself"
                                                                    : "not in remote.writable");
    auto value = params::parse_value(*d, payload);
    if (!value)
        return make_error(ExitCode::Config, "remote: {}: {}", safe_quote(topic), value.error().message);
    return Request(SetParam{d->id, std::move(*value)});
}

constexpr std::string_view apply_at_key = " apply_at=";

// Splits " apply_at=<seconds>" off the end of `payload`.
Result<ApplyAt> take_apply_at(std::string_view topic, std::string_view& payload) {
    const std::size_t at = payload.rfind(apply_at_key);
    if (at == std::string_view::npos) return ApplyAt{};
    const std::string text(trim(payload.substr(at + apply_at_key.size())));
    payload = trim(payload.substr(0, at));
    char* end = nullptr;
    const double seconds = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
    // Up to the year 2262, where nanoseconds since 1970 leave an int64.
    if (text.empty() || *end != '\0' || !(seconds > 0.0 && seconds < 9.2e9))
        return make_error(ExitCode::Config,
                          "remote: {}: apply_at '{}' is not a time in seconds since the Unix epoch (such as "
                          "1764590402.5)",
                          safe_quote(topic), safe_quote(text));
    return ApplyAt{std::llround(seconds * 1e9)};
}

}  // namespace

Result<Request> parse_request(const RemoteSettings& s, const Inbound& m) {
    const std::string_view rest = after_prefix(s, m.topic);
    const bool command_topic = rest.starts_with("set/") || rest == "preset/set" || rest == "command";
    // Before anything else: a retained command is never applied, whatever it holds.
    if (command_topic && m.retained) return Request(RetainedCommand{});
    if (m.size > max_payload_bytes)
        return make_error(ExitCode::Config, "remote: {}: payload of {} bytes refused (at most {})",
                          safe_quote(m.topic), m.size, max_payload_bytes);
    std::string_view payload = trim(m.payload);
    if (m.topic == "homeassistant/status") {
        if (payload == "online") return Request(HomeAssistantOnline{});
        return Request(Ignored{});
    }
    if (command_topic && payload.empty()) return Request(Ignored{});  // a retained message cleared
    if (rest.starts_with("set/") || rest == "preset/set") {
        auto apply_at = take_apply_at(m.topic, payload);
        if (!apply_at) return apply_at.error();
        if (rest == "preset/set")
            return Request(SelectPreset{payload == "none" ? "" : std::string(payload), *apply_at});
        auto request = set_param(s, m.topic, rest.substr(4), payload);
        if (request) std::get<SetParam>(*request).apply_at_ns = *apply_at;
        return request;
    }
    if (rest == "command") {
        for (std::size_t i = 0; i < std::size(command_names); ++i)
            if (payload == command_names[i]) return Request(static_cast<Command>(i));
        return make_error(ExitCode::Config,
                          "remote: {}: unknown command '{}' (one of: next-preset, previous-preset, save, "
                          "screenshot, reload)",
                          safe_quote(m.topic), safe_quote(payload));
    }
    return make_error(ExitCode::Config,
                      "remote: {}: not a command topic (set/<parameter>, preset/set, command)",
                      safe_quote(m.topic));
}

}  // namespace puddle::remote
