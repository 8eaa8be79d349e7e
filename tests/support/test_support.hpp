#pragma once
// Helpers shared by the tests: temporary folders, image statistics and comparisons, the shared assets.

#include <cstdlib>
#include <filesystem>
#include <string>

#include "assets/image.hpp"

namespace puddle::test {

// A fresh folder under the system temp dir, removed when the object dies.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
    std::string write(const std::string& name, const std::string& contents) const;

private:
    std::filesystem::path path_;
};

// Sets an environment variable for its lifetime, then unsets it.
struct ScopedEnv {
    ScopedEnv(const char* name, const std::string& value) : name_(name) { ::setenv(name, value.c_str(), 1); }
    ~ScopedEnv() { ::unsetenv(name_); }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;
    const char* name_;
};

// A file's bytes, empty when it cannot be read.
std::string read_file(const std::filesystem::path& p);

// ../shared/assets, or empty when the shared folder is absent (tests then GTEST_SKIP with a message).
std::string shared_assets_dir();

struct ImageDiff {
    int max_channel_diff = 0;  // largest |a - b| over all channels, 0..255
    double mean_abs_diff = 0;  // over all channels, 0..255
    double fraction_over = 0;  // pixels with any channel differing by more than the threshold
};
ImageDiff compare_images(const assets::Image& a, const assets::Image& b, int threshold);

// Mean of linearised-by-nothing 8-bit luma (0..255) over a rectangle (x0, y0 inclusive, x1, y1 exclusive).
double mean_luma(const assets::Image& img, int x0, int y0, int x1, int y1);
double mean_luma(const assets::Image& img);
// Standard deviation of luma over a rectangle: a measure of contrast.
double luma_stddev(const assets::Image& img, int x0, int y0, int x1, int y1);

// A shell command run to its end: stdout and stderr together, and its exit code (-1 when it did not exit).
struct CommandResult {
    int exit_code = -1;
    std::string output;
};
CommandResult run_command(const std::string& command);
// The shell command that runs one of the build's own programs (an absolute path): the path itself, or
// under deploy/cross-build.sh --test the cross build's emulator (qemu-user) followed by it.
std::string program_command(const std::string& path);
// The puddle binary under test, run with these arguments.
CommandResult run_puddle(const std::string& args);

// Where tests write pictures worth looking at when they fail (build/test-output).
std::filesystem::path output_dir();

}  // namespace puddle::test
