#pragma once
// An estimate of a fragment shader's per-pixel cost read from its GLSL (after #include splicing): texture
// fetches and ALU operations. Not a compiler: it preprocesses the #ifdef variants, then walks main()
// counting arithmetic and comparison operators as one operation each, built-in functions by weight
// (normalize 3, pow 3, refract 6, ...), and user functions at every call. Loops count their literal trip
// count (capped by `max_loop_iterations`); both sides of a branch count, so the figure is the longest path
// and then some. Vector and scalar operations weigh the same. It moves when the shader's work moves,
// which is what the benchmark's baseline needs; a GPU's own compiler folds some of it away.

#include <string>
#include <string_view>

namespace puddle::bench {

struct ShaderCost {
    int texture_fetches = 0;
    int alu_ops = 0;
};

// `source` is an assembled shader (gpu::assemble_shader); `max_loop_iterations` caps any loop, e.g. a
// ray-march that breaks after a uniform number of steps.
ShaderCost estimate_shader_cost(std::string_view source, int max_loop_iterations = 64);

}  // namespace puddle::bench
