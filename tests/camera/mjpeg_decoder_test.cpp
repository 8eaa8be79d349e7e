// MJPEG frames: a truncated frame is refused rather than shown grey where its data ran out.
#include "camera/mjpeg_decoder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "camera/fake_v4l2_device.hpp"

namespace puddle::test {
namespace {

const std::filesystem::path cases = std::filesystem::path(PUDDLE_SHARED_DIR) / "cases" / "camera";

std::vector<std::byte> read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::vector<char> chars{std::istreambuf_iterator<char>(in), {}};
    return std::vector<std::byte>(reinterpret_cast<const std::byte*>(chars.data()),
                                  reinterpret_cast<const std::byte*>(chars.data()) + chars.size());
}

TEST(MjpegDecoder, RefusesATruncatedFrame) {
    const auto whole = encode_jpeg(64, 48, 200, 40, 30);
    camera::MjpegDecoder decoder;
    ASSERT_TRUE(decoder.decode(whole, 64, 48));
    auto r = decoder.decode(cut_in_scan(whole), 64, 48);
    ASSERT_FALSE(r) << "libjpeg only warns (JWRN_JPEG_EOF) and fills the rest with grey";
    EXPECT_EQ(r.error().message, "premature end of data");
    EXPECT_TRUE(decoder.decode(whole, 64, 48)) << "the next whole frame decodes";
}

TEST(MjpegDecoder, RefusesTheSharedTruncatedCase) {
    if (!std::filesystem::exists(cases / "truncated.jpg"))
        GTEST_SKIP() << "needs " << cases.string() << " (the shared cases folder beside the source tree)";
    camera::MjpegDecoder decoder;
    const auto good = read_bytes(cases / "good.jpg");
    auto g = decoder.decode(good, 64, 48);
    ASSERT_TRUE(g) << g.error().message;
    const auto* px = reinterpret_cast<const std::uint8_t*>(decoder.rgba().data()) + (40 * 64 + 32) * 4;
    EXPECT_GT(px[0], 200) << "the bottom half of good.jpg is red";
    EXPECT_LT(px[1], 60);
    auto t = decoder.decode(read_bytes(cases / "truncated.jpg"), 64, 48);
    ASSERT_FALSE(t);
    EXPECT_EQ(t.error().message, "premature end of data");
}

}  // namespace
}  // namespace puddle::test
