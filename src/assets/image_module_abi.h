/* The plain C interface between puddle and libpuddle-images.so, the module that reads images through
 * OpenImageIO. OpenImageIO's Debian package maps about 140 MB of shared libraries (OpenCV, GDAL,
 * openvdb, FFmpeg...), so puddle loads the module with dlopen() only when an image file is read; a run
 * with the procedural sky never maps any of it. C, not C++, so nothing but these types crosses. */
#ifndef PUDDLE_IMAGE_MODULE_ABI_H
#define PUDDLE_IMAGE_MODULE_ABI_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bumped whenever a type or function below changes; puddle refuses a module of another version. */
#define PUDDLE_IMAGE_MODULE_ABI_VERSION 2
/* The one exported symbol: returns the module's table of functions. */
#define PUDDLE_IMAGE_MODULE_ENTRY "puddle_image_module"

enum PuddleImageWant {
    PUDDLE_IMAGE_RGBA8 = 0,    /* 8 bits per channel */
    PUDDLE_IMAGE_RGBA32F = 1,  /* float, the file's values */
    PUDDLE_IMAGE_AS_STORED = 2 /* float for float files (.hdr, .exr, float TIFF), else 8 bits */
};

/* Called once the size is known: returns width * height * 4 channels of the given type (float when
 * is_float, else unsigned char), tightly packed, top row first; or NULL to give up. */
typedef void* (*PuddleImageAlloc)(void* context, int width, int height, int is_float);

/* What a file's header says, read without decoding a pixel. */
struct PuddleImageInfo {
    int width;    /* pixels */
    int height;   /* pixels */
    int is_float; /* 1 for float files (.hdr, .exr, float TIFF): PUDDLE_IMAGE_AS_STORED reads them as float */
};

struct PuddleImageModule {
    int abi_version; /* PUDDLE_IMAGE_MODULE_ABI_VERSION */
    /* Reads `path` as RGBA (grey, grey+alpha and RGB expanded; channels past four dropped) into the
     * buffer `alloc` returns. Returns 1 on success; on failure 0 and, in `error`, one line saying why
     * (without the path), e.g. "cannot decode: ...". */
    int (*read)(const char* path, int want, PuddleImageAlloc alloc, void* context, char* error,
                size_t error_size);
    /* Opens `path` and reads its header only (no pixel is decoded, no pixel buffer allocated) into
     * `info`, so that callers can refuse a size or shape before paying for the decode. Returns 1 on
     * success; on failure 0 and one line in `error`, as `read` does. Since version 2. */
    int (*probe)(const char* path, struct PuddleImageInfo* info, char* error, size_t error_size);
};

typedef const struct PuddleImageModule* (*PuddleImageModuleEntry)(void);

#ifdef __cplusplus
}
#endif

#endif
