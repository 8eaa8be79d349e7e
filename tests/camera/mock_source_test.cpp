#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>

#include "assets/image_io.hpp"
#include "camera/camera_source.hpp"
#include "camera/fake_v4l2_device.hpp"
#include "support/image_bomb.hpp"
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

// Issue 15: the folder's limits are checked on the headers, before any image is decoded. The PNG claims
// 16000x16000 (976 MiB as RGBA8) over a few bytes: decoded first, it cost 2 GB of peak memory and ended
// in the decoder's error rather than the limit's.
TEST(MockSource, AnImageOverTheFolderLimitIsRefusedFromItsHeaderWithoutDecoding) {
    TempDir dir;
    const std::string bomb = dir.write("bomb.png", png_claiming(16000, 16000));
    FakeV4l2Device unused;
    const std::size_t peak_before = peak_rss_bytes();
    auto src = camera::open_camera_source(unused, {.device = "mock:" + bomb});
    ASSERT_FALSE(src);
    EXPECT_EQ(src.error().code, ExitCode::Asset);
    EXPECT_EQ(src.error().message, "camera: mock:" + bomb + ": the images up to " + bomb +
                                       " take 976 MiB decoded; the limit is 256 MiB");
    EXPECT_LT(peak_rss_bytes() - peak_before, std::size_t{64} << 20) << "no pixel buffer was allocated";
}

TEST(MockSource, AnImageOfAnotherSizeIsRefusedFromItsHeaderWithoutDecoding) {
    TempDir dir;
    write_solid((dir / "0.png").string(), 10);
    const std::string bomb = dir.write("a.png", png_claiming(16000, 16000));
    FakeV4l2Device unused;
    const std::size_t peak_before = peak_rss_bytes();
    auto src = camera::open_camera_source(unused, {.device = "mock:" + dir.path().string()});
    ASSERT_FALSE(src);
    EXPECT_EQ(src.error().message, "camera: mock:" + dir.path().string() + ": " + bomb +
                                       " is 16000x16000, the first image is 8x4; all must match");
    EXPECT_LT(peak_rss_bytes() - peak_before, std::size_t{64} << 20) << "no pixel buffer was allocated";
}

// Shutdown while a mock folder is decoded on the camera worker: the decoding stops between two images.
TEST(MockSource, AStopRequestEndsTheDecodingBeforeTheNextImage) {
    TempDir dir;
    write_solid((dir / "a.png").string(), 10);
    write_solid((dir / "b.png").string(), 20);
    FakeV4l2Device unused;
    std::stop_source stop;
    stop.request_stop();
    auto src =
        camera::open_camera_source(unused, {.device = "mock:" + dir.path().string()}, stop.get_token());
    ASSERT_FALSE(src);
    EXPECT_EQ(src.error().message,
              "camera: mock:" + dir.path().string() + ": opening stopped before " + (dir / "a.png").string());
}

TEST(MockSource, RenamedFolderIsAnUnplugAndComesBackWhenReopened) {
    TempDir dir;
    const auto folder = dir / "camera", away = dir / "camera-unplugged";
    std::filesystem::create_directory(folder);
    write_solid((folder / "a.png").string(), 30);
    FakeV4l2Device unused;
    const camera::CaptureRequest request{.device = "mock:" + folder.string(), .fps = 10.0};
    auto src = camera::open_camera_source(unused, request);
    ASSERT_TRUE(src) << src.error().message;
    auto first = (*src)->poll(0.0);
    ASSERT_TRUE(first && first->has_value());

    std::filesystem::rename(folder, away);
    auto same_tick = (*src)->poll(0.05);
    ASSERT_TRUE(same_tick) << "nothing is due within the tick, so nothing is checked";
    EXPECT_FALSE(same_tick->has_value());
    auto gone = (*src)->poll(0.1);
    ASSERT_FALSE(gone) << "the next frame due finds the folder gone";
    EXPECT_NE(gone.error().message.find("went away"), std::string::npos) << gone.error().message;
    EXPECT_NE(gone.error().message.find(folder.string()), std::string::npos) << gone.error().message;
    EXPECT_FALSE(camera::open_camera_source(unused, request)) << "unplugged: opening fails";

    std::filesystem::rename(away, folder);
    auto back = camera::open_camera_source(unused, request);
    ASSERT_TRUE(back) << back.error().message;
    auto frame = (*back)->poll(0.2);
    ASSERT_TRUE(frame && frame->has_value());
    EXPECT_EQ(std::to_integer<int>((**frame).data[0]), 30);
}

// A failed mock is retried only when this changes (systems/sky/camera_system.cpp): it must change with every
// edit a user makes to the folder, and stay put while nothing does.
TEST(MockSource, StampChangesWhenTheFolderOrItsFilesDoAndOnlyThen) {
    TempDir dir;
    const auto folder = dir / "camera";
    std::filesystem::create_directory(folder);
    write_solid((folder / "a.png").string(), 10);
    const std::string first = camera::mock_source_stamp(folder.string());
    EXPECT_EQ(camera::mock_source_stamp(folder.string()), first) << "nothing changed";
    EXPECT_NE(first.find("a.png"), std::string::npos) << first;

    write_solid((folder / "b.png").string(), 20);  // one more image
    const std::string added = camera::mock_source_stamp(folder.string());
    EXPECT_NE(added, first);

    std::ofstream(folder / "b.png", std::ios::binary | std::ios::app) << "x";  // rewritten in place
    const std::string grown = camera::mock_source_stamp(folder.string());
    EXPECT_NE(grown, added);

    std::filesystem::rename(folder, dir / "away");
    const std::string gone = camera::mock_source_stamp(folder.string());
    EXPECT_NE(gone, grown);
    EXPECT_NE(gone.find("No such file or directory"), std::string::npos) << gone;

    EXPECT_EQ(camera::source_stamp({.device = "mock:" + folder.string()}),
              "mock:" + folder.string() + "\n" + gone);
    EXPECT_EQ(camera::source_stamp({.device = "/dev/video0"}), "") << "a V4L2 device is always retried";
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
