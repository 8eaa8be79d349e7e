#pragma once
// The effective parameters as the broker publishes them (retained): one JSON document on <prefix>/state
// ({"rain.intensity": 0.3, "water.tint": [0.02, 0.04, 0.05], "scene.kind": "puddle", ...}) and one topic
// per parameter, <prefix>/state/<name>, holding the value in the syntax <prefix>/set/<name> takes
// (0.3, true, 0.02,0.04,0.05, puddle), so a simple consumer can echo it back.

#include <nlohmann/json.hpp>
#include <string>

#include "params/param_store.hpp"

namespace puddle::remote {

std::string state_document(const params::Params& params);
// The reply on <prefix>/error: {"topic": "...", "error": "..."}. Bytes that are not UTF-8 (a message may
// quote a payload of any bytes) become U+FFFD: JSON must be UTF-8, and nlohmann's dump() would throw.
std::string error_document(const std::string& topic, const std::string& message);
// Every document the broker gets is dumped this way: invalid UTF-8 replaced, never an exception.
std::string dump_json(const nlohmann::json& doc);
// The value as <prefix>/set/<name> reads it back (registry.hpp's parse_value).
std::string set_syntax(const params::ParamValue& value);

}  // namespace puddle::remote
