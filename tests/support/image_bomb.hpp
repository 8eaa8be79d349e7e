#pragma once
// Image bombs for the header-first tests: a PNG whose header claims any size over a few bytes
// of data, and the process's peak memory, to show that such a file was refused without being decoded.

#include <cstddef>
#include <string>

namespace puddle::test {

// The bytes of a PNG file (PNG specification, 2nd edition, sections 5.2 to 5.6 and 11.2.2): the signature,
// an IHDR saying `width` x `height`, 8-bit RGB, then one IDAT of a few bytes that is no valid zlib stream,
// and IEND. Every chunk carries its correct CRC-32, so a reader gets past the header and fails only when
// it decodes the pixels.
std::string png_claiming(int width, int height);

// The process's peak resident memory so far (getrusage's ru_maxrss), in bytes.
std::size_t peak_rss_bytes();

}  // namespace puddle::test
