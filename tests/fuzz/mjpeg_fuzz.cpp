// Fuzz target: the MJPEG frame decoder (MjpegDecoder::decode) on whatever bytes a camera delivers. The
// stream is negotiated at 64x48 (the size of ../shared/cases/camera/good.jpg and of the seeds made by
// puddle-fuzz-seeds), so a frame of another size must be refused. A decoded frame fills exactly
// 64 * 48 * 4 bytes; a corrupt one is an error, never a crash or a read past the input.

#include <span>

#include "camera/mjpeg_decoder.hpp"
#include "fuzz_support.hpp"

using namespace puddle;

namespace {
constexpr int negotiated_width = 64, negotiated_height = 48;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // One decoder for all inputs, as a camera source keeps one for the life of the stream: a failed
    // frame must leave it ready for the next.
    static camera::MjpegDecoder decoder;
    const auto frame = std::as_bytes(std::span(data, size));
    const auto decoded = decoder.decode(frame, negotiated_width, negotiated_height);
    if (!decoded) {
        PUDDLE_FUZZ_CHECK(!decoded.error().message.empty(), "an error without a message");
        return 0;
    }
    PUDDLE_FUZZ_CHECK(decoder.rgba().size() == std::size_t{negotiated_width} * negotiated_height * 4,
                      "decoded %zu bytes", decoder.rgba().size());
    return 0;
}
