// puddle-image-diff: are two pictures the same within a tolerance? Used by tests/vm/run to compare
// QEMU's screendump (PPM) of the KMS screen with the headless render (PNG) of the same frame and seed.
// Any format OpenImageIO reads works. Prints one line with the figures; exit 0 within the tolerance,
// 1 outside it (or different sizes), 2 for bad arguments or an unreadable file.
//
//   puddle-image-diff A B [--mean M] [--threshold T] [--fraction F] [--diff OUT.png]
//     --mean M       largest mean absolute difference over all channels, 0..255 (default 1.5)
//     --threshold T  a pixel is "off" when a channel differs by more than T (default 32)
//     --fraction F   largest fraction of pixels that may be off (default 0.01)
//     --diff OUT     writes |A - B| times 4 as a PNG, to look at

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"

namespace {

int usage(const char* why) {
    std::fprintf(stderr,
                 "puddle-image-diff: %s\nusage: puddle-image-diff A B [--mean M] [--threshold T] "
                 "[--fraction F] [--diff OUT.png]\n",
                 why);
    return 2;
}

bool parse_number(const char* text, double& out) {
    char* end = nullptr;
    out = std::strtod(text, &end);
    return end != text && *end == '\0' && out >= 0;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace puddle;
    std::string paths[2], diff_path;
    int path_count = 0;
    double mean_max = 1.5, threshold = 32, fraction_max = 0.01;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        double* number = arg == "--mean"        ? &mean_max
                         : arg == "--threshold" ? &threshold
                         : arg == "--fraction"  ? &fraction_max
                                                : nullptr;
        if (number || arg == "--diff") {
            if (i + 1 >= argc) return usage("an option lacks its value");
            if (number && !parse_number(argv[++i], *number)) return usage("not a number >= 0");
            if (!number) diff_path = argv[++i];
        } else if (arg.starts_with("--") || path_count == 2) {
            return usage("unexpected argument");
        } else {
            paths[path_count++] = std::string(arg);
        }
    }
    if (path_count != 2) return usage("two pictures are needed");

    assets::Image images[2];
    for (int i = 0; i < 2; ++i) {
        auto image = assets::read_image(paths[i]);
        if (!image) {
            std::fprintf(stderr, "puddle-image-diff: %s\n", image.error().message.c_str());
            return 2;
        }
        images[i] = std::move(*image);
    }
    const assets::Image& a = images[0];
    const assets::Image& b = images[1];
    if (a.width != b.width || a.height != b.height) {
        std::printf("sizes differ: %dx%d against %dx%d\n", a.width, a.height, b.width, b.height);
        return 1;
    }
    const test::ImageDiff d = test::compare_images(a, b, static_cast<int>(threshold));
    const bool within = d.mean_abs_diff <= mean_max && d.fraction_over <= fraction_max;
    std::printf(
        "%dx%d, mean difference %.3f/255 (at most %.3g), %.3f%% of pixels off by more than %g "
        "(at most %.3g%%), largest %d/255: %s\n",
        a.width, a.height, d.mean_abs_diff, mean_max, d.fraction_over * 100, threshold, fraction_max * 100,
        d.max_channel_diff, within ? "match" : "DIFFERENT");
    if (!diff_path.empty()) {
        assets::Image diff = assets::Image::make(a.width, a.height);
        for (std::size_t i = 0; i < diff.data.size(); ++i)
            diff.data[i] =
                (i % 4 == 3)
                    ? 255
                    : static_cast<std::uint8_t>(std::min(255, 4 * std::abs(int(a.data[i]) - int(b.data[i]))));
        if (auto r = assets::write_png(diff_path, diff); !r)
            std::fprintf(stderr, "puddle-image-diff: %s\n", r.error().message.c_str());
    }
    return within ? 0 : 1;
}
