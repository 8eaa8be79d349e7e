#pragma once
// The one place GLES headers are included. Only src/gpu and src/platform may include this file.
// gl2ext.h needs gl3.h's types first: the order is not alphabetical, so clang-format leaves it alone.
// clang-format off
#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>
// clang-format on
