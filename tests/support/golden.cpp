#include "support/golden.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"

namespace puddle::test {

void check_golden(const char* name, const assets::Image& image) {
    ASSERT_FALSE(image.empty());
    const std::string path = std::string(PUDDLE_SOURCE_DIR) + "/tests/golden/" + name + ".png";
    if (std::getenv("PUDDLE_UPDATE_GOLDEN")) {
        ASSERT_TRUE(assets::write_png(path, image).ok());
        GTEST_SKIP() << "wrote " << path;
    }
    auto golden = assets::read_image(path);
    ASSERT_TRUE(golden.ok()) << golden.error().message << " (PUDDLE_UPDATE_GOLDEN=1 makes it)";
    const ImageDiff d = compare_images(image, *golden, 32);
    if (d.mean_abs_diff > 1.5 || d.fraction_over > 0.01)
        (void)assets::write_png((output_dir() / (std::string(name) + ".actual.png")).string(), image);
    EXPECT_LE(d.mean_abs_diff, 1.5) << name << ": see test-output/" << name << ".actual.png";
    EXPECT_LE(d.fraction_over, 0.01) << name;
}

}  // namespace puddle::test
