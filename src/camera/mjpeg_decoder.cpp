#include "camera/mjpeg_decoder.hpp"

#include <jpeglib.h>

#include <csetjmp>
#include <cstdio>

namespace puddle::camera {

namespace {

struct ErrorManager {
    jpeg_error_mgr base;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void on_error(j_common_ptr info) {
    auto* e = reinterpret_cast<ErrorManager*>(info->err);
    info->err->format_message(info, e->message);
    std::longjmp(e->jump, 1);
}

void ignore_message(j_common_ptr) {}  // corrupt-data warnings: the frame still decodes

}  // namespace

Result<void> MjpegDecoder::decode(std::span<const std::byte> jpeg, int expected_width, int expected_height) {
    // Only trivially destructible locals between setjmp and longjmp.
    jpeg_decompress_struct info{};
    ErrorManager errors{};
    info.err = jpeg_std_error(&errors.base);
    errors.base.error_exit = on_error;
    errors.base.output_message = ignore_message;
    const std::size_t needed =
        static_cast<std::size_t>(expected_width) * static_cast<std::size_t>(expected_height) * 4;
    if (rgba_.size() != needed) rgba_.resize(needed);  // once per negotiated size
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&info);
        return make_error(ExitCode::Runtime, "camera: MJPEG frame ({} bytes): {}", jpeg.size(),
                          errors.message);
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(jpeg.data()),
                 static_cast<unsigned long>(jpeg.size()));
    jpeg_read_header(&info, TRUE);
    info.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&info);
    if (static_cast<int>(info.output_width) != expected_width ||
        static_cast<int>(info.output_height) != expected_height) {
        const unsigned w = info.output_width, h = info.output_height;
        jpeg_destroy_decompress(&info);
        return make_error(ExitCode::Runtime,
                          "camera: MJPEG frame is {}x{}, the stream was negotiated at {}x{}", w, h,
                          expected_width, expected_height);
    }
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
