#pragma once
#include <string_view>
namespace puddle::app {
std::string_view version();
}
