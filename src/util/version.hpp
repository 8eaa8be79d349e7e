#pragma once
// Puddle's version, from CMakeLists.txt's project(VERSION) (PUDDLE_VERSION, defined for every layer).

#include <string_view>

namespace puddle {

constexpr std::string_view version() {
    return PUDDLE_VERSION;
}

}  // namespace puddle
