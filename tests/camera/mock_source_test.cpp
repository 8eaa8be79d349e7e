#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>

#include "assets/image_io.hpp"
#include "camera/camera_source.hpp"
#include "camera/fake_v4l2_device.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

void write_solid(const std::string& path, std::uint8_t r) {
    assets::Image img = assets::Image::make(8, 4);
    for (int i = 0; i < 8 * 4; ++i) {
        img.data[std::size_t(i) * 4] = r;
        img.data[std::size_t(i) * 4 + 3] = 255;
    }
    ASSERT_TRUE(assets::write_png(path, img));
}

TEST(MockSource, PlaysAFolderInALoopAtTheRequestedRate) {
    TempDir dir;
    write_solid((dir / "a.png").string(), 10);
    write_solid((dir / "b.png").string(), 20);
    FakeV4l2Device unused;
    auto src = camera::open_camera_source(unused, {.device = "mock:" + dir.path().string(), .fps = 10.0});
    ASSERT_TRUE(src) << src.error().message;
    std::vector<int> seen;  // first red byte of each new frame, polled at 60 fps for 0.5 s
    for (int i = 0; i < 30; ++i) {
        auto f = (*src)->poll(i / 60.0);
        ASSERT_TRUE(f);
        if (f->has_value()) seen.push_back(std::to_integer<int>((**f).data[0]));
    }
    EXPECT_EQ(seen, (std::vector<int>{10, 20, 10, 20, 10})) << "a new image every 0.1 s, in name order";
    EXPECT_EQ(unused.opens(), 0) << "mock: never touches a device";
}

// Issue 15: a mock folder is decoded into memory whole, so its size is bounded before it is read.
TEST(MockSource, AFolderOfTooManyImagesIsRefusedBeforeDecodingAny) {
    TempDir dir;
    for (int i = 0; i < 257; ++i) std::ofstream(dir / fmt::format("{:03}.png", i)) << "not decoded";
    FakeV4l2Device unused;
    auto src = camera::open_camera_source(unused, {.device = "mock:" + dir.path().string()});
    ASSERT_FALSE(src);
    EXPECT_EQ(src.error().code, ExitCode::Asset);
    EXPECT_EQ(src.error().message, "camera: mock:" + dir.path().string() +
                                       ": the folder holds more than 256 images; the limit is 256");
}

TEST(MockSource, MissingPathIsAnAssetErrorNamingIt) {
    FakeV4l2Device unused;
    auto src = camera::open_camera_source(unused, {.device = "mock:/nonexistent/room.png"});
    ASSERT_FALSE(src);
    EXPECT_EQ(src.error().code, ExitCode::Asset);
    EXPECT_NE(src.error().message.find("/nonexistent/room.png"), std::string::npos) << src.error().message;
}

}  // namespace
}  // namespace puddle::test
