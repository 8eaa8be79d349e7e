#pragma once
// Shader sources embedded from shaders_gles/ at build time, and their assembly into one GLSL string:
// `#version 300 es`, the variant's #defines, then the file with `#include "x.glsl"` spliced in. `#line`
// directives carry a file number, so a compiler message "3:42(7): error" maps back to "water.glsl:42".

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.hpp"

namespace puddle::gpu {

struct EmbeddedShader {
    const char* name;
    const char* text;
};
std::span<const EmbeddedShader> embedded_shaders();  // generated: build/generated/embedded_shaders.cpp

struct AssembledShader {
    std::string source;
    std::vector<std::string> files;  // file number -> name, for mapping compiler messages back
};

// Looks up `name` in the embedded table (or `lookup` when given, for tests).
using ShaderLookup = std::string_view (*)(std::string_view name);
Result<AssembledShader> assemble_shader(std::string_view name, std::span<const std::string> defines,
                                        ShaderLookup lookup = nullptr);
// Rewrites a driver's info log so each "N:LINE" names the file: "puddle.frag:120: error: ...".
std::string map_shader_log(std::string_view log, const AssembledShader& shader);

}  // namespace puddle::gpu
