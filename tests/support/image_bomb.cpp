#include "support/image_bomb.hpp"

#include <sys/resource.h>

#include <cstdint>

namespace puddle::test {
namespace {

// CRC-32 as PNG uses it (ISO 3309 / ITU-T V.42, polynomial 0xEDB88320, reflected), bit by bit.
std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (const char ch : bytes) {
        c ^= static_cast<std::uint8_t>(ch);
        for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
}

std::string big_endian(std::uint32_t v) {
    return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
            static_cast<char>(v)};
}

// Length, type, data, CRC over type and data.
std::string chunk(const std::string& type, const std::string& data) {
    return big_endian(static_cast<std::uint32_t>(data.size())) + type + data + big_endian(crc32(type + data));
}

}  // namespace

std::string png_claiming(int width, int height) {
    const std::string signature("\x89PNG\r\n\x1a\n", 8);
    // Bit depth 8, colour type 2 (RGB), compression 0, filter 0, no interlace.
    const std::string ihdr = big_endian(static_cast<std::uint32_t>(width)) +
                             big_endian(static_cast<std::uint32_t>(height)) +
                             std::string("\x08\x02\x00\x00\x00", 5);
    // A zlib header (deflate, 32 KiB window) followed by a reserved block type: a decoder stops here.
    const std::string idat("\x78\x9c\xff\xff\xff\xff", 6);
    return signature + chunk("IHDR", ihdr) + chunk("IDAT", idat) + chunk("IEND", "");
}

std::size_t peak_rss_bytes() {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

}  // namespace puddle::test
