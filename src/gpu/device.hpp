#pragma once
// The Device: the one creation path for GPU objects (create_* from labelled descriptors) and the owner
// of what every pass shares (the empty vertex array for fullscreen triangles, the extension entry points).
// Made once a context is current (by a display backend); lives as a World resource.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gpu/buffer.hpp"
#include "gpu/capabilities.hpp"
#include "gpu/external_image.hpp"
#include "gpu/frame_target.hpp"
#include "gpu/gpu_timer.hpp"
#include "gpu/handle.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/pipeline_compiler.hpp"
#include "gpu/render_pass.hpp"
#include "gpu/texture.hpp"
#include "util/result.hpp"

namespace puddle::gpu {

struct DeviceOptions {
    bool forbid_float_targets = false;  // exercise the fixed-point fallbacks on any GPU
    // Engine: build the pipelines of looks chosen while running on a worker thread (the display's worker
    // context), as the binary does. Off: at once on the frame thread, so a test or benchmark that sets a
    // look sees it in the next frame.
    bool background_compiles = false;
};

struct GlExtensions;  // gpu/gl_extensions.hpp, private to the gpu layer

namespace detail {
void delete_vertex_array(std::uint32_t id);
}

// A pipeline being built for the frame loop (Device::request_pipeline); empty when none is.
struct PipelineRequest {
    std::shared_ptr<CompileJob> job;            // linking on the compiler's worker
    std::optional<Result<Pipeline>> built_now;  // no worker: built at request time
    bool active() const { return job || built_now; }
};

class Device {
public:
    explicit Device(const DeviceOptions& options = {});
    Device(Device&&) noexcept = default;
    Device& operator=(Device&&) noexcept = default;

    const Capabilities& caps() const { return caps_; }
    // The extension entry points, looked up once when the Device was made (gpu/gl_extensions.hpp).
    const GlExtensions& extensions() const { return *extensions_; }

    // Errors name the label, what was asked for and why: "gpu: texture 'environment' (cube 6 x 4096x4096
    // SRGB8_ALPHA8, 13 levels, 512.0 MiB): glTexStorage2D: GL_OUT_OF_MEMORY". Exit code GpuMemory for
    // GL_OUT_OF_MEMORY (a smaller size may fit), Runtime for a size beyond the GPU's limits, any other GL
    // error or an incomplete render target framebuffer.
    Result<Texture> create_texture(const TextureDesc& desc);
    Sampler create_sampler(const SamplerDesc& desc);
    // Errors as create_texture's: "gpu: buffer 'live drops' (1024 bytes): glBufferData: GL_OUT_OF_MEMORY".
    Result<Buffer> create_buffer(const BufferDesc& desc);
    // Compile and link errors name the shader file and line: "gpu: wave_step.frag:31: error: ...".
    Result<Pipeline> create_pipeline(const PipelineDesc& desc);
    // From now on request_pipeline links on a worker thread in `context` (a display's worker context).
    // Should the worker fail to make it current, take_pipeline logs that once and builds at once.
    void start_background_compiles(std::unique_ptr<WorkerContext> context);
    bool compiles_in_background() const { return compiler_ && !worker_failed_; }
    // For the frame loop: starts building desc without waiting for it (see gpu/pipeline_compiler.hpp);
    // builds it at once when background compiles were not started.
    PipelineRequest request_pipeline(PipelineDesc desc);
    // The requested pipeline, or its error as create_pipeline's, once it is built: the request is then
    // empty. Nothing while the worker is still on it.
    std::optional<Result<Pipeline>> take_pipeline(PipelineRequest& request);
    RenderPass begin_pass(const RenderPassDesc& desc);
    // Times frames on the GPU (gpu/gpu_timer.hpp); one that measures nothing without timer queries.
    GpuTimer create_gpu_timer();
    // An EGLImage (from a dmabuf or a GL texture) as an External texture (external_image.cpp).
    Result<ExternalImage> create_external_image(const ExternalImageDesc& desc);
    // What create_external_image can import with this context and its EGL display.
    ExternalImageSupport external_image_support() const;

    // Reads a frame into `rgba` (size.x * size.y * 4 bytes), top row first, as PNG files expect.
    void read_pixels(const FrameTarget& target, std::span<std::uint8_t> rgba);
    // Reads level 0 of a 2D texture (or of one cube face) as 4 floats per texel (integers converted as
    // is, 8-bit formats as stored / 255), rows in GL order (row 0 = t 0). For tests and tools, not for
    // the frame loop.
    std::vector<float> read_texture(const Texture& texture, int face = 0);
    // Waits until the GPU is done: benchmarks time whole passes with it.
    void finish();
    // Every GL error flag raised since the last call (glGetError until GL_NO_ERROR), as names joined by
    // ", " ("GL_INVALID_VALUE, GL_OUT_OF_MEMORY"); empty when there was none. Clears the flags. For
    // checks (the soak test), not for every frame.
    std::string take_errors();

private:
    // Reads a linked program's uniforms and binds its samplers and blocks (frame thread).
    Result<Pipeline> adopt_program(const PipelineDesc& desc, GlHandle<detail::delete_program> program);

    std::unique_ptr<PipelineCompiler> compiler_;  // first: its worker stops before the device's objects die
    bool worker_failed_ = false;                  // its context could not be made current: build at once
    Capabilities caps_;
    std::shared_ptr<const GlExtensions> extensions_;  // an ExternalImage keeps it for eglDestroyImageKHR
    GlHandle<detail::delete_vertex_array> empty_vao_;
};

}  // namespace puddle::gpu
