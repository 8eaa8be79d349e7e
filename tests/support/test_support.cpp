#include "support/test_support.hpp"

#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

namespace puddle::test {

TempDir::TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("puddle-test-" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
}

std::string TempDir::write(const std::string& name, const std::string& contents) const {
    const auto p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << contents;
    return p.string();
}

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string shared_assets_dir() {
    const std::filesystem::path p = std::filesystem::path(PUDDLE_SHARED_DIR) / "assets";
    return std::filesystem::is_directory(p) ? p.string() : std::string();
}

ImageDiff compare_images(const assets::Image& a, const assets::Image& b, int threshold) {
    ImageDiff d;
    if (a.width != b.width || a.height != b.height) {
        d.max_channel_diff = 255;
        d.mean_abs_diff = 255;
        d.fraction_over = 1;
        return d;
    }
    long long sum = 0, over = 0;
    const std::size_t pixels = std::size_t(a.width) * a.height;
    for (std::size_t i = 0; i < pixels; ++i) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int diff = std::abs(int(a.data[i * 4 + c]) - int(b.data[i * 4 + c]));
            sum += diff;
            worst = std::max(worst, diff);
        }
        d.max_channel_diff = std::max(d.max_channel_diff, worst);
        if (worst > threshold) ++over;
    }
    d.mean_abs_diff = double(sum) / double(pixels * 3);
    d.fraction_over = double(over) / double(pixels);
    return d;
}

static double luma_at(const assets::Image& img, int x, int y) {
    const std::uint8_t* p = img.pixel8(x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

double mean_luma(const assets::Image& img, int x0, int y0, int x1, int y1) {
    double sum = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += luma_at(img, x, y);
    return sum / double((x1 - x0) * (y1 - y0));
}

double mean_luma(const assets::Image& img) {
    return mean_luma(img, 0, 0, img.width, img.height);
}

double luma_stddev(const assets::Image& img, int x0, int y0, int x1, int y1) {
    const double mean = mean_luma(img, x0, y0, x1, y1);
    double sq = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sq += (luma_at(img, x, y) - mean) * (luma_at(img, x, y) - mean);
    return std::sqrt(sq / double((x1 - x0) * (y1 - y0)));
}

CommandResult run_command(const std::string& command) {
    CommandResult r;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return r;
    char buf[4096];
    while (std::fgets(buf, sizeof buf, pipe)) r.output += buf;
    const int status = pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

std::string program_command(const std::string& path) {
    const std::string emulator = PUDDLE_TEST_EMULATOR;
    return emulator.empty() ? path : emulator + " " + path;
}

CommandResult run_puddle(const std::string& args) {
    return run_command(program_command(PUDDLE_BINARY) + " " + args);
}

std::filesystem::path output_dir() {
    const auto p = std::filesystem::current_path() / "test-output";
    std::filesystem::create_directories(p);
    return p;
}

}  // namespace puddle::test
