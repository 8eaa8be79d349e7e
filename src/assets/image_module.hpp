#pragma once
// Finds and loads libpuddle-images.so (OpenImageIO behind a C interface, image_module_abi.h) on the
// first image read. Looked for, in order: $PUDDLE_IMAGE_MODULE; lib/puddle/ beside the executable (the
// build tree); ../lib/puddle/ from the executable's folder (installed: /usr/bin/puddle reads
// /usr/lib/puddle/libpuddle-images.so).

#include <string>

#include "assets/image_module_abi.h"
#include "util/result.hpp"

namespace puddle::assets {

inline constexpr const char* image_module_file = "libpuddle-images.so";
inline constexpr const char* image_module_env = "PUDDLE_IMAGE_MODULE";

// The path the module is (or would be) loaded from.
std::string image_module_path();
// The module, loaded once per process; later calls return the same table or the same error, which
// names the path and what dlopen() said.
Result<const PuddleImageModule*> image_module();

}  // namespace puddle::assets
