#pragma once
// A pipeline: a linked vertex + fragment program plus the bindings it expects, like a WebGPU render
// pipeline with its bind group layout written into the descriptor. Made by Device::create_pipeline.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/handle.hpp"

namespace puddle::gpu {

// How the pass's output meets what the target holds: replace it; blend by the output's alpha (overlays
// drawn over a finished frame); or Lit: target * (1 + output), so what is drawn shows as light in
// proportion to what lies behind it (rain streaks catching the scene's light: glBlendFunc(DST_COLOR, ONE)).
enum class Blend { Replace, Alpha, Lit };

struct PipelineDesc {
    std::string label;
    std::string vertex = "fullscreen.vert";   // file in shaders_gles/
    std::string fragment;                     // file in shaders_gles/
    std::vector<std::string> defines;         // variants: "METHOD_RAYMARCH", "MAX_DROPS 128"
    std::vector<std::string> textures;        // sampler uniform names; texture unit = position here
    std::vector<std::string> uniform_blocks;  // uniform block names; binding = position here
    Blend blend = Blend::Replace;
};

namespace detail {
void delete_program(std::uint32_t id);
}

// An active uniform's location, looked up once (Pipeline::uniform) so that a pass sets it every frame
// without searching names; -1: the shader does not use it (setting it is then a no-op, as in GL).
struct UniformLocation {
    int value = -1;
    bool active() const { return value >= 0; }
};

class Pipeline {
public:
    Pipeline() = default;
    std::uint32_t id() const { return program_.get(); }  // the GL program name; 0 until built
    const std::string& label() const { return label_; }
    // Location of an active uniform, or -1 when the shader does not use it (setting it is then a no-op).
    int location(std::string_view uniform) const;
    UniformLocation uniform(std::string_view name) const { return {location(name)}; }
    std::span<const std::string> uniform_names() const { return names_; }
    Blend blend() const { return blend_; }

private:
    friend class Device;
    GlHandle<detail::delete_program> program_;
    std::string label_;
    std::vector<std::string> names_;
    std::vector<int> locations_;
    Blend blend_ = Blend::Replace;
};

}  // namespace puddle::gpu
