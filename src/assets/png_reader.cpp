#include "assets/png_reader.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace puddle::assets::png {

namespace {

// libpng's error text, kept by on_error before it longjmp()s back to the setjmp in read_header/read_rows.
struct Errors {
    char message[200] = "";
};

[[noreturn]] void on_error(png_structp png, png_const_charp text) {
    auto* errors = static_cast<Errors*>(png_get_error_ptr(png));
    std::snprintf(errors->message, sizeof errors->message, "%s", text);
    png_longjmp(png, 1);
}

// Warnings (an iCCP profile libpng dislikes, a text chunk it skips) do not change the pixels.
void on_warning(png_structp, png_const_charp) {}

// One file being read and libpng's structures for it, released together.
class Reader {
public:
    explicit Reader(const char* path) : file_(std::fopen(path, "rb")) {
        open_errno_ = errno;
        if (!file_) return;
        png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors_, on_error, on_warning);
        if (png_) info_ = png_create_info_struct(png_);
    }
    ~Reader() {
        if (png_) png_destroy_read_struct(&png_, info_ ? &info_ : nullptr, nullptr);
        if (file_) std::fclose(file_);
    }
    Reader(const Reader&) = delete;
    Reader& operator=(const Reader&) = delete;

    // Why the file could not be read at all, or empty when it can be.
    std::string unusable() const {
        if (!file_) return std::string("cannot read: ") + std::strerror(open_errno_);
        if (!png_ || !info_) return "cannot read: no memory for libpng";
        return {};
    }
    std::string decode_error() const {
        // libpng's default reader says "Read Error" when fread() comes up short.
        if (std::strcmp(errors_.message, "Read Error") == 0)
            return "cannot decode: the file ends early (truncated?)";
        return std::string("cannot decode: ") +
               (errors_.message[0] ? errors_.message : "unknown libpng error");
    }

    std::FILE* file_;
    int open_errno_ = 0;
    png_structp png_ = nullptr;
    png_infop info_ = nullptr;
    Errors errors_;
};

// Reads the header and asks libpng for RGBA rows of 8 or 16 bits (host byte order). The setjmp is here,
// in a frame holding nothing with a destructor, as longjmp() requires. false on a libpng error.
bool read_header(Reader& r) {
    if (setjmp(png_jmpbuf(r.png_))) return false;
    png_init_io(r.png_, r.file_);
    png_read_info(r.png_, r.info_);
    png_set_expand(r.png_);  // palette to RGB, grey below 8 bits to 8, tRNS to an alpha channel
    png_set_gray_to_rgb(r.png_);
    png_set_add_alpha(r.png_, 0xffff, PNG_FILLER_AFTER);  // opaque where the file has no alpha
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    if (png_get_bit_depth(r.png_, r.info_) == 16) png_set_swap(r.png_);  // PNG stores 16 bits big-endian
#endif
    png_set_interlace_handling(r.png_);
    png_read_update_info(r.png_, r.info_);
    return true;
}

bool read_rows(Reader& r, png_bytep* rows) {
    if (setjmp(png_jmpbuf(r.png_))) return false;
    png_read_image(r.png_, rows);
    return true;
}

}  // namespace

bool has_signature(const char* path) {
    std::FILE* f = std::fopen(path, "rb");
    if (!f) return false;
    png_byte head[8] = {};
    const bool png =
        std::fread(head, 1, sizeof head, f) == sizeof head && png_sig_cmp(head, 0, sizeof head) == 0;
    std::fclose(f);
    return png;
}

int probe(const char* path, PuddleImageInfo* info, std::string& why) {
    Reader r(path);
    if (why = r.unusable(); !why.empty()) return 0;
    if (!read_header(r)) return why = r.decode_error(), 0;
    *info = PuddleImageInfo{.width = static_cast<int>(png_get_image_width(r.png_, r.info_)),
                            .height = static_cast<int>(png_get_image_height(r.png_, r.info_)),
                            .is_float = 0};
    return 1;
}

int read(const char* path, int want, PuddleImageAlloc alloc, void* context, std::string& why) {
    Reader r(path);
    if (why = r.unusable(); !why.empty()) return 0;
    if (!read_header(r)) return why = r.decode_error(), 0;
    const std::size_t width = png_get_image_width(r.png_, r.info_);
    const std::size_t height = png_get_image_height(r.png_, r.info_);
    const int depth = png_get_bit_depth(r.png_, r.info_);
    const std::size_t row_bytes = png_get_rowbytes(r.png_, r.info_);
    if (png_get_channels(r.png_, r.info_) != 4 || (depth != 8 && depth != 16) ||
        row_bytes != width * 4 * static_cast<std::size_t>(depth / 8))
        return why = "cannot decode: unexpected PNG layout after expansion", 0;

    const bool as_float = want == PUDDLE_IMAGE_RGBA32F;
    void* dst = alloc(context, static_cast<int>(width), static_cast<int>(height), as_float ? 1 : 0);
    if (dst == nullptr) return why = "cannot read: no memory for the pixels", 0;
    // 8-bit RGBA is decoded straight into the caller's buffer; the rest through a staging copy.
    std::vector<png_byte> staging;
    png_bytep target = static_cast<png_bytep>(dst);
    if (as_float || depth == 16) {
        staging.resize(row_bytes * height);
        target = staging.data();
    }
    std::vector<png_bytep> rows(height);
    for (std::size_t y = 0; y < height; ++y) rows[y] = target + y * row_bytes;
    if (!read_rows(r, rows.data())) return why = r.decode_error(), 0;

    const std::size_t samples = width * height * 4;
    if (depth == 16) {
        auto sample = [&](std::size_t i) {  // host order (png_set_swap)
            std::uint16_t v;
            std::memcpy(&v, staging.data() + 2 * i, 2);
            return v;
        };
        if (as_float) {
            auto* out = static_cast<float*>(dst);
            for (std::size_t i = 0; i < samples; ++i) out[i] = static_cast<float>(sample(i)) / 65535.0f;
        } else {
            auto* out = static_cast<std::uint8_t*>(dst);
            for (std::size_t i = 0; i < samples; ++i)
                out[i] = static_cast<std::uint8_t>((sample(i) + 128u) / 257u);  // rounded, as OpenImageIO
        }
    } else if (as_float) {
        auto* out = static_cast<float*>(dst);
        for (std::size_t i = 0; i < samples; ++i) out[i] = static_cast<float>(staging[i]) / 255.0f;
    }
    return 1;
}

}  // namespace puddle::assets::png
