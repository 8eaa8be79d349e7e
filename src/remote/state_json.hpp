#pragma once
// The effective parameters as the broker publishes them (retained): one JSON document on <prefix>/state
// ({"rain.intensity": 0.3, "water.tint": [0.02, 0.04, 0.05], "scene.kind": "puddle", ...}) and one topic
// per parameter, <prefix>/state/<name>, holding the value in the syntax <prefix>/set/<name> takes
// (0.3, true, 0.02,0.04,0.05, puddle), so a simple consumer can echo it back.

#include <string>

#include "params/param_store.hpp"

namespace puddle::remote {

std::string state_document(const params::Params& params);
// The value as <prefix>/set/<name> reads it back (registry.hpp's parse_value).
std::string set_syntax(const params::ParamValue& value);

}  // namespace puddle::remote
