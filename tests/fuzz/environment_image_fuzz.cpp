// Fuzz target: `environment.image` as one file, read the way the sky is loaded: OpenImageIO through
// libpuddle-images.so (PNG, JPEG, HDR, EXR or TIFF, chosen by the first input byte, which picks the file
// name's extension), the size limits checked from the header before decoding (image_limits.hpp), float
// values made safe to upload, then the panorama or cube cross decision and the cut into faces.
//
// OpenImageIO and the codecs are not instrumented: coverage and checks are Puddle's own. Whatever comes
// back must be a 2:1 panorama or six square faces of one size, within the limits, with every pixel
// present and every float finite.

#include <cmath>
#include <cstdlib>
#include <span>

#include "assets/environment_images.hpp"
#include "assets/image_limits.hpp"
#include "fuzz_support.hpp"

using namespace puddle;
using namespace puddle::assets;

namespace {

void check_image(const Image& image, const char* what) {
    PUDDLE_FUZZ_CHECK(image.width > 0 && image.height > 0, "%s is %dx%d", what, image.width, image.height);
    PUDDLE_FUZZ_CHECK(check_image_size("fuzz", image.width, image.height, image.format).ok(),
                      "%s is %dx%d, past the limits", what, image.width, image.height);
    PUDDLE_FUZZ_CHECK(image.data.size() == std::size_t(image.width) * image.height * image.bytes_per_pixel(),
                      "%s holds %zu bytes for %dx%d", what, image.data.size(), image.width, image.height);
    if (image.format != PixelFormat::RGBA32F) return;
    const float* v = image.pixelf(0, 0);
    for (std::size_t i = 0, n = std::size_t(image.width) * image.height * 4; i < n; ++i)
        PUDDLE_FUZZ_CHECK(std::isfinite(v[i]) && v[i] >= 0, "%s has %g at value %zu", what, double(v[i]), i);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    fuzz::quiet_logs();
    // The module beside this build's puddle, unless the caller chose one.
    setenv("PUDDLE_IMAGE_MODULE", PUDDLE_FUZZ_IMAGE_MODULE, 0);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    constexpr const char* names[] = {"sky.png", "sky.jpg", "sky.hdr", "sky.exr", "sky.tif"};
    const std::string path = fuzz::write_scratch_file(names[data[0] % 5], std::span(data + 1, size - 1));
    auto env = load_environment_images(path);
    if (!env) {
        PUDDLE_FUZZ_CHECK(env.error().code == ExitCode::Asset, "exit code %d for: %s", int(env.error().code),
                          env.error().message.c_str());
        PUDDLE_FUZZ_CHECK(env.error().message.find(path) != std::string::npos,
                          "the message misses the path: %s", env.error().message.c_str());
        return 0;
    }
    if (env->faces) {
        const int side = env->faces->faces[0].width;
        for (const Image& face : env->faces->faces) {
            check_image(face, "a cube face");
            PUDDLE_FUZZ_CHECK(
                face.width == side && face.height == side && face.format == env->faces->faces[0].format,
                "faces of %dx%d and %dx%d", side, side, face.width, face.height);
        }
    } else {
        check_image(env->panorama, "the panorama");
        PUDDLE_FUZZ_CHECK(env->panorama.width == 2 * env->panorama.height, "a panorama of %dx%d",
                          env->panorama.width, env->panorama.height);
    }
    return 0;
}
