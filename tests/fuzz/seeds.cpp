// puddle-fuzz-seeds FOLDER: writes the binary seed inputs the fuzz targets start from, made with Puddle's
// own encoder and OpenImageIO so that no binary blob is checked in. One subfolder per target, named
// after it; tests/fuzz/run copies the text seeds (tests/fuzz/corpus/) and ../shared/cases beside them.

#include <OpenImageIO/imageio.h>
#include <linux/videodev2.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "camera/mjpeg_encoder.hpp"

namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const void* bytes, std::size_t size) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary)
        .write(static_cast<const char*>(bytes), static_cast<std::streamsize>(size));
}

// Zig-zag and gradients: every channel varies, so a decoder that drops a row or a plane shows.
std::vector<std::uint8_t> pattern(int width, int height, int channels) {
    std::vector<std::uint8_t> pixels(std::size_t(width) * height * channels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                pixels[(std::size_t(y) * width + x) * channels + c] =
                    static_cast<std::uint8_t>(c == 0   ? x * 255 / width
                                              : c == 1 ? (x + y) % 16 * 16
                                                       : y * 255 / height);
    return pixels;
}

std::vector<std::byte> jpeg(int width, int height, int quality) {
    return puddle::camera::encode_jpeg(pattern(width, height, 3), width, height, quality);
}

// camera_frame_fuzz's input: the format header, then one frame [length lo, length hi, flags, payload].
void camera_seed(const fs::path& path, int fourcc_choice, int width, int height, int padding,
                 const std::vector<std::byte>& frame) {
    std::vector<std::uint8_t> bytes{static_cast<std::uint8_t>(fourcc_choice),
                                    static_cast<std::uint8_t>((width - 1) & 0xff),
                                    static_cast<std::uint8_t>((width - 1) >> 8),
                                    static_cast<std::uint8_t>((height - 1) & 0xff),
                                    static_cast<std::uint8_t>((height - 1) >> 8),
                                    static_cast<std::uint8_t>(padding),
                                    2,
                                    0};
    for (int repeat = 0; repeat < 2; ++repeat) {
        bytes.push_back(static_cast<std::uint8_t>(frame.size() & 0xff));
        bytes.push_back(static_cast<std::uint8_t>(frame.size() >> 8));
        bytes.push_back(0);
        for (std::byte b : frame) bytes.push_back(static_cast<std::uint8_t>(b));
    }
    write(path, bytes.data(), bytes.size());
}

// environment_image_fuzz's input: the extension's index, then the file.
bool image_seed(const fs::path& folder, int extension, int width, int height, bool as_float) {
    constexpr const char* extensions[] = {".png", ".jpg", ".hdr", ".exr", ".tif"};
    const fs::path temp = fs::temp_directory_path() / (std::string("puddle-seed") + extensions[extension]);
    auto out = OIIO::ImageOutput::create(temp.string());
    if (!out) return false;
    const OIIO::ImageSpec spec(width, height, 3, as_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!out->open(temp.string(), spec)) return false;
    bool ok;
    if (as_float) {
        std::vector<float> pixels;
        for (std::uint8_t v : pattern(width, height, 3)) pixels.push_back(float(v) / 64.0f);
        ok = out->write_image(OIIO::TypeDesc::FLOAT, pixels.data());
    } else {
        ok = out->write_image(OIIO::TypeDesc::UINT8, pattern(width, height, 3).data());
    }
    out->close();
    if (!ok) return false;
    std::ifstream in(temp, std::ios::binary);
    std::vector<char> bytes{static_cast<char>(extension)};
    bytes.insert(bytes.end(), std::istreambuf_iterator<char>(in), {});
    fs::remove(temp);
    write(folder / (std::to_string(width) + "x" + std::to_string(height) + extensions[extension]),
          bytes.data(), bytes.size());
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: puddle-fuzz-seeds FOLDER\n");
        return 2;
    }
    const fs::path root = argv[1];

    const auto frame = jpeg(64, 48, 85);
    if (frame.empty()) {
        std::fprintf(stderr, "puddle-fuzz-seeds: encode_jpeg failed\n");
        return 1;
    }
    write(root / "mjpeg" / "64x48.jpg", frame.data(), frame.size());
    write(root / "mjpeg" / "64x48-truncated.jpg", frame.data(), frame.size() / 2);
    const auto low = jpeg(64, 48, 10);
    write(root / "mjpeg" / "64x48-q10.jpg", low.data(), low.size());
    const auto other = jpeg(32, 24, 85);
    write(root / "mjpeg" / "32x24.jpg", other.data(), other.size());

    const auto yuv = [](std::size_t n) {
        std::vector<std::byte> bytes(n);
        for (std::size_t i = 0; i < n; ++i) bytes[i] = static_cast<std::byte>(i * 7);
        return bytes;
    };
    camera_seed(root / "camera_frame" / "yuyv-64x48", 0, 64, 48, 0, yuv(64 * 2 * 48));
    camera_seed(root / "camera_frame" / "yuyv-65x48-padded", 0, 65, 48, 14, yuv(144 * 48));
    camera_seed(root / "camera_frame" / "nv12-64x48", 1, 64, 48, 0, yuv(64 * 48 * 3 / 2));
    camera_seed(root / "camera_frame" / "nv12-65x49-stride80", 1, 65, 49, 15, yuv(80 * 49 + 80 * 25));
    camera_seed(root / "camera_frame" / "mjpeg-64x48", 2, 64, 48, 0, frame);

    int images = 0;
    for (int extension = 0; extension < 5; ++extension) {
        const bool as_float = extension == 2 || extension == 3;
        images += image_seed(root / "environment_image", extension, 16, 8, as_float);   // a panorama
        images += image_seed(root / "environment_image", extension, 16, 12, as_float);  // a horizontal cross
        images += image_seed(root / "environment_image", extension, 12, 16, as_float);  // a vertical cross
    }
    if (images == 0) {
        std::fprintf(stderr, "puddle-fuzz-seeds: OpenImageIO wrote no image\n");
        return 1;
    }

    for (const auto& [w, h, layout] :
         {std::tuple{16, 12, 3}, std::tuple{12, 16, 3}, std::tuple{64, 48, 1}, std::tuple{48, 64, 2},
          std::tuple{17, 12, 3}, std::tuple{256, 128, 0}}) {
        const std::uint8_t bytes[] = {
            static_cast<std::uint8_t>((w - 1) & 0xff), static_cast<std::uint8_t>((w - 1) >> 8),
            static_cast<std::uint8_t>((h - 1) & 0xff), static_cast<std::uint8_t>((h - 1) >> 8),
            static_cast<std::uint8_t>(layout)};
        write(root / "cube_cross" / (std::to_string(w) + "x" + std::to_string(h)), bytes, sizeof bytes);
    }
    std::printf("puddle-fuzz-seeds: wrote seeds into %s (%d images)\n", root.c_str(), images);
    return 0;
}
