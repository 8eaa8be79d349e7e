#pragma once
// The one place GLES headers are included. Private to the gpu layer: only src/gpu/*.cpp, the private
// src/gpu/gl_*.hpp headers and src/platform may include this file (ctest gpu_headers_gl_free keeps every
// other header GL-free).
// gl2ext.h needs gl3.h's types first: the order is not alphabetical, so clang-format leaves it alone.
// clang-format off
#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>
// clang-format on

#include <cstdint>
#include <type_traits>

// Public headers carry GL object names as std::uint32_t and uniform locations as int (gpu/handle.hpp).
static_assert(std::is_same_v<GLuint, std::uint32_t>, "GLuint must be std::uint32_t");
static_assert(std::is_same_v<GLint, int>, "GLint must be int");
