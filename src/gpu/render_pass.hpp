#pragma once
// One render pass: a colour target with load and store operations, then draws. LoadOp::Clear is
// glClear; StoreOp::Discard is glInvalidateFramebuffer (cheap on tiled mobile GPUs). Begun by
// Device::begin_pass; ended by end() or the destructor.

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <string_view>

#include "gpu/frame_target.hpp"
#include "gpu/pipeline.hpp"

namespace puddle::gpu {

class Buffer;
class Device;
struct GlExtensions;
class Pipeline;
class Sampler;
class Texture;

// What a pass does with the target's old contents. As in WebGPU there is no default: every pass says
// which, so a forgotten clear cannot show the last frame's leftovers.
enum class LoadOp { Clear, Load, DontCare };
// A LoadOp that must be given: a RenderPassDesc without `.load = ...` does not compile.
struct RequiredLoadOp {
    constexpr RequiredLoadOp(LoadOp o) : op(o) {}  // implicit: `.load = LoadOp::Clear` reads as it should
    LoadOp op;
};
enum class StoreOp { Store, Discard };

struct RenderPassDesc {
    std::string_view label;
    FrameTarget target;  // texture, or framebuffer 0 of the current surface
    RequiredLoadOp load;
    glm::vec4 clear{0, 0, 0, 1};
    StoreOp store = StoreOp::Store;
    // Only rows [first, first + count) of the target are drawn (glScissor; row 0 is GL's bottom row, t = 0),
    // so a long pass can be split over frames. Count 0: every row. With a count, load must not be DontCare.
    glm::ivec2 rows{0, 0};
};

class RenderPass {
public:
    RenderPass(const RenderPass&) = delete;
    RenderPass& operator=(const RenderPass&) = delete;
    ~RenderPass() { end(); }

    RenderPass& set_pipeline(const Pipeline& pipeline);
    RenderPass& set_texture(int unit, const Texture& texture, const Sampler& sampler);
    RenderPass& set_uniform_buffer(int binding, const Buffer& buffer);
    // Uniforms by name on the current pipeline; names the shader does not use are ignored.
    RenderPass& set(std::string_view name, float v);
    RenderPass& set(std::string_view name, int v);
    RenderPass& set(std::string_view name, glm::vec2 v);
    RenderPass& set(std::string_view name, glm::ivec2 v);
    RenderPass& set(std::string_view name, glm::vec3 v);
    RenderPass& set(std::string_view name, glm::vec4 v);
    RenderPass& set(std::string_view name, const glm::mat3& v);
    // Arrays, from element 0: elements past the shader's array size are ignored (GLES 3.0 section 2.12.6).
    RenderPass& set(std::string_view name, std::span<const float> v);
    RenderPass& set(std::string_view name, std::span<const int> v);
    RenderPass& set(std::string_view name, std::span<const glm::ivec2> v);
    RenderPass& set(std::string_view name, std::span<const glm::vec4> v);
    // Uniforms at locations looked up once (Pipeline::uniform): the parameter bindings.
    RenderPass& set(UniformLocation at, float v);
    RenderPass& set(UniformLocation at, int v);
    RenderPass& set(UniformLocation at, glm::vec3 v);
    // One triangle covering the target; the vertex shader makes it from gl_VertexID.
    void draw_fullscreen();
    // `count` quads, each a 4-vertex triangle strip, one instance per quad: the vertex shader places them
    // from gl_InstanceID and gl_VertexID (0..3, corners (0,0), (1,0), (0,1), (1,1)); no vertex buffer.
    void draw_quads(int count);
    void end();

private:
    friend class Device;
    RenderPass(const RenderPassDesc& desc, const GlExtensions& extensions);
    const Pipeline* pipeline_ = nullptr;
    StoreOp store_ = StoreOp::Store;
    bool is_default_framebuffer_ = false;
    bool scissored_ = false;
    bool ended_ = false;
    const GlExtensions* extensions_ = nullptr;  // the Device's: debug groups
};

}  // namespace puddle::gpu
