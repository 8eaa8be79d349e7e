#include "camera/mjpeg_decoder.hpp"

// clang-format off
#include <cstdio>  // before jpeglib.h, which uses FILE without including it
#include <jpeglib.h>
#include <jerror.h>
// clang-format on

#include <csetjmp>
#include <cstring>

namespace puddle::camera {

namespace {

struct ErrorManager {
    jpeg_error_mgr base;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void stop(j_common_ptr info) {
    auto* e = reinterpret_cast<ErrorManager*>(info->err);
    const int code = info->err->msg_code;
    if (code == JWRN_JPEG_EOF || code == JWRN_HIT_MARKER)
        std::strcpy(e->message, "premature end of data");
    else
        info->err->format_message(info, e->message);
    std::longjmp(e->jump, 1);
}

// Warnings that mean the pixels are damaged: libjpeg carries on (grey where data ran out, smears after a
// bad code), so the frame is refused instead. Other warnings (a trailing byte before EOI, which many
// webcams send, an unknown JFIF revision) leave a sound picture and are ignored, as are trace messages.
void on_message(j_common_ptr info, int level) {
    if (level >= 0) return;  // trace output
    switch (info->err->msg_code) {
        case JWRN_JPEG_EOF:
        case JWRN_HIT_MARKER:
        case JWRN_HUFF_BAD_CODE:
        case JWRN_ARITH_BAD_CODE:
        case JWRN_MUST_RESYNC:
        case JWRN_NOT_SEQUENTIAL:
        case JWRN_BOGUS_PROGRESSION:
            stop(info);
        default:
            return;
    }
}

}  // namespace

Result<void> MjpegDecoder::decode(std::span<const std::byte> jpeg, int expected_width, int expected_height) {
    if (jpeg.empty()) return make_error(ExitCode::Runtime, "an empty frame");
    // Only trivially destructible locals between setjmp and longjmp.
    jpeg_decompress_struct info{};
    ErrorManager errors{};
    info.err = jpeg_std_error(&errors.base);
    errors.base.error_exit = stop;
    errors.base.emit_message = on_message;
    const std::size_t needed =
        static_cast<std::size_t>(expected_width) * static_cast<std::size_t>(expected_height) * 4;
    if (rgba_.size() != needed) rgba_.resize(needed);  // once per negotiated size
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&info);
        return make_error(ExitCode::Runtime, "{}", errors.message);
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(jpeg.data()),
                 static_cast<unsigned long>(jpeg.size()));
    jpeg_read_header(&info, TRUE);
    // Checked before decoding: a frame of another size is refused without decoding it.
    if (static_cast<long>(info.image_width) != expected_width ||
        static_cast<long>(info.image_height) != expected_height) {
        const unsigned w = info.image_width, h = info.image_height;
        jpeg_destroy_decompress(&info);
        return make_error(ExitCode::Runtime, "a {}x{} frame in a {}x{} stream", w, h, expected_width,
                          expected_height);
    }
    info.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&info);
    const std::size_t row = static_cast<std::size_t>(expected_width) * 4;
    while (info.output_scanline < info.output_height) {
        auto* line = reinterpret_cast<unsigned char*>(rgba_.data() + info.output_scanline * row);
        jpeg_read_scanlines(&info, &line, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return {};
}

}  // namespace puddle::camera
