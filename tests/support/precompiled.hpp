#pragma once
// The test executables' precompiled header (tests/CMakeLists.txt, puddle_test_executable): GoogleTest,
// fmt and the standard headers most tests include. Parsing these took about half of each test file's
// compile; a test still includes what it uses, so it compiles without this header too.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
