#pragma once
// A config parsed from text for a test: the test fails (not aborts) on a parse error, naming it, and goes
// on with an empty Config.

#include <gtest/gtest.h>

#include "params/config_loader.hpp"

namespace puddle::test {

inline params::Config parsed_config(const char* text) {
    auto c = params::parse_config(text, "test.toml");
    EXPECT_TRUE(c) << c.error().message;
    return c ? *c : params::Config{};
}

}  // namespace puddle::test
