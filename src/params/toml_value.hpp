#pragma once
// A TOML value read as a parameter's value, shared by the config's sections and its [[schedule]] tables'
// `set`. Private to src/params: its users include toml++ already.

#include <toml++/toml.h>

#include <string>

#include "params/registry.hpp"
#include "util/result.hpp"

namespace puddle::params {

// The line a node starts on.
int toml_line(const toml::node& n);
// The value as written, on one line: numbers in their shortest form (1e+300, not toml++'s
// 1.0000000000000001e+300), arrays as [1, 2, 3].
std::string toml_text(const toml::node& n);
// The node as the declared kind. Numbers are checked against the range before they are narrowed
// (number_value); the error names the key and the value as written. The caller still calls validate().
Result<ParamValue> toml_param_value(const ParamDecl& d, const toml::node& n);

}  // namespace puddle::params
