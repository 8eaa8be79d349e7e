#pragma once
// The one place GLES headers are included. Only src/gpu and src/platform may include this file.
#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>
