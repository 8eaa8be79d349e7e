#pragma once
// PNG files read with libpng directly, inside libpuddle-images.so, instead of through OpenImageIO 2.4,
// whose PNG reader has libpng print "libpng error: ..." on stderr outside Puddle's log and leaks the
// error string it builds in its read callback each time libpng longjmp()s out of it (a truncated file).
// Here libpng's errors come back as one line, its warnings (an odd iCCP profile) are dropped, and nothing
// is left behind. The pixels equal OpenImageIO's: palette, grey and low bit depths expanded to RGB(A),
// tRNS to alpha, straight alpha, no gamma applied, 16-bit samples rounded to 8 bits (v / 257) or scaled
// to floats (v / 65535). PNG: ISO/IEC 15948 (W3C PNG, 2nd edition); libpng manual, "Reading PNG files".

#include <string>

#include "assets/image_module_abi.h"

namespace puddle::assets::png {

// True when the file starts with the 8-byte PNG signature.
bool has_signature(const char* path);

// The header's width and height (is_float 0), without decoding a pixel. 0 with `why` set on failure.
int probe(const char* path, PuddleImageInfo* info, std::string& why);

// Decodes into alloc's RGBA buffer (RGBA8, or floats for PUDDLE_IMAGE_RGBA32F; PUDDLE_IMAGE_AS_STORED is
// RGBA8, PNG holding no floats). 0 with `why` ("cannot decode: ...") on failure.
int read(const char* path, int want, PuddleImageAlloc alloc, void* context, std::string& why);

}  // namespace puddle::assets::png
