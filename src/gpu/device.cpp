#include "gpu/device.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstring>

#include "gpu/gl.hpp"
#include "gpu/gl_debug_labels.hpp"
#include "gpu/gl_errors.hpp"
#include "gpu/gl_extensions.hpp"
#include "gpu/gl_formats.hpp"
#include "gpu/program_link.hpp"

namespace puddle::gpu {

namespace detail {
void delete_vertex_array(std::uint32_t id) {
    glDeleteVertexArrays(1, &id);
}
}  // namespace detail

namespace {

GLint gl_wrap(Wrap w) {
    switch (w) {
        case Wrap::Clamp:
            return GL_CLAMP_TO_EDGE;
        case Wrap::Repeat:
            return GL_REPEAT;
        case Wrap::Mirror:
            return GL_MIRRORED_REPEAT;
    }
    return GL_CLAMP_TO_EDGE;
}

}  // namespace

Device::Device(const DeviceOptions& options)
    : caps_(probe_capabilities(options.forbid_float_targets)),
      extensions_(std::make_shared<const GlExtensions>(GlExtensions::load())) {
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    empty_vao_ = GlHandle<detail::delete_vertex_array>(vao);
    glBindVertexArray(vao);
}

Result<Texture> Device::create_texture(const TextureDesc& desc) {
    const bool cube = desc.kind == TextureKind::Cube;
    const int limit = cube ? caps_.max_cube_map_size : caps_.max_texture_size;
    if (desc.width < 1 || desc.height < 1 || desc.width > limit || desc.height > limit)
        return make_error(ExitCode::Runtime,
                          "gpu: texture '{}' ({}): {}x{} is outside 1 to {}, this GPU's largest {}",
                          desc.label, describe_storage(desc), desc.width, desc.height, limit,
                          cube ? "cube map face" : "texture");
    Texture t;
    t.desc_ = desc;
    GLuint id = 0;
    glGenTextures(1, &id);
    t.id_ = GlHandle<detail::delete_texture>(id);
    const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    (void)take_gl_error();  // an earlier call's error is not this texture's
    glBindTexture(target, id);
    glTexStorage2D(target, std::max(1, desc.mip_levels), gl_format(desc.format).internal, desc.width,
                   desc.height);
    if (const GLenum e = take_gl_error(); e != GL_NO_ERROR)
        return make_error(exit_code_for(e), "gpu: texture '{}' ({}): glTexStorage2D: {}", desc.label,
                          describe_storage(desc), gl_error_name(e));
    // Integer and unfilterable float textures are incomplete with the default mipmap filter.
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER,
                    desc.mip_levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, std::max(0, desc.mip_levels - 1));
    label_object(*extensions_, GL_TEXTURE, id, desc.label);
    if (desc.render_target) {
        glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer());
        const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        const GLenum e = take_gl_error();
        if (status != GL_FRAMEBUFFER_COMPLETE || e != GL_NO_ERROR)
            return make_error(exit_code_for(e), "gpu: render target '{}' ({}): framebuffer: {}{}", desc.label,
                              describe_storage(desc), framebuffer_status_name(status),
                              e != GL_NO_ERROR ? ", " + gl_error_name(e) : std::string());
    }
    return t;
}

Sampler Device::create_sampler(const SamplerDesc& desc) {
    Sampler s;
    GLuint id = 0;
    glGenSamplers(1, &id);
    s.id_ = GlHandle<detail::delete_sampler>(id);
    GLint min = desc.min == Filter::Linear ? GL_LINEAR : GL_NEAREST;
    if (desc.mipmaps) min = desc.min == Filter::Linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST;
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, min);
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, desc.mag == Filter::Linear ? GL_LINEAR : GL_NEAREST);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, gl_wrap(desc.wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, gl_wrap(desc.wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_R, gl_wrap(desc.wrap));
    if (caps_.anisotropic_filtering && desc.anisotropy > 1.0f)
        glSamplerParameterf(id, GL_TEXTURE_MAX_ANISOTROPY_EXT,
                            std::min(desc.anisotropy, caps_.max_anisotropy));
    label_object(*extensions_, GL_SAMPLER, id, desc.label);
    return s;
}

Result<Buffer> Device::create_buffer(const BufferDesc& desc) {
    Buffer b;
    GLuint id = 0;
    glGenBuffers(1, &id);
    b.id_ = GlHandle<detail::delete_buffer>(id);
    b.size_ = desc.size;
    (void)take_gl_error();
    glBindBuffer(GL_UNIFORM_BUFFER, id);
    glBufferData(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(desc.size), nullptr, GL_DYNAMIC_DRAW);
    if (const GLenum e = take_gl_error(); e != GL_NO_ERROR)
        return make_error(exit_code_for(e), "gpu: buffer '{}' ({} bytes): glBufferData: {}", desc.label,
                          desc.size, gl_error_name(e));
    label_object(*extensions_, GL_BUFFER_KHR, id, desc.label);
    return b;
}

Result<Pipeline> Device::create_pipeline(const PipelineDesc& desc) {
    auto program = link_program(desc);
    if (!program) return program.error();
    return adopt_program(desc, std::move(program).value());
}

void Device::start_background_compiles(std::unique_ptr<WorkerContext> context) {
    compiler_ = std::make_unique<PipelineCompiler>(std::move(context));
}

PipelineRequest Device::request_pipeline(PipelineDesc desc) {
    PipelineRequest request;
    if (compiler_ && !worker_failed_)
        request.job = compiler_->submit(std::move(desc));
    else
        request.built_now = create_pipeline(desc);
    return request;
}

std::optional<Result<Pipeline>> Device::take_pipeline(PipelineRequest& request) {
    if (request.built_now) return std::exchange(request.built_now, std::nullopt);
    if (!request.job || !request.job->done.load(std::memory_order_acquire)) return std::nullopt;
    const std::shared_ptr<CompileJob> job = std::exchange(request.job, nullptr);
    if (job->worker_unavailable) {
        if (!worker_failed_)
            spdlog::warn("{}; building pipelines on the frame thread", job->result->error().message);
        worker_failed_ = true;
        return create_pipeline(job->desc);
    }
    if (!*job->result) return Result<Pipeline>(job->result->error());
    return adopt_program(job->desc, std::move(*job->result).value());
}

Result<Pipeline> Device::adopt_program(const PipelineDesc& desc, GlHandle<detail::delete_program> program) {
    Pipeline p;
    p.label_ = desc.label;
    p.blend_ = desc.blend;
    p.program_ = std::move(program);
    const GLuint prog = p.program_.get();
    glUseProgram(prog);  // binding it makes a program linked in the worker's context current here
    label_object(*extensions_, GL_PROGRAM_KHR, prog, desc.label);

    GLint count = 0, max_len = 0;
    glGetProgramiv(prog, GL_ACTIVE_UNIFORMS, &count);
    glGetProgramiv(prog, GL_ACTIVE_UNIFORM_MAX_LENGTH, &max_len);
    std::string name(static_cast<std::size_t>(max_len) + 1, '\0');
    for (GLint i = 0; i < count; ++i) {
        GLsizei len = 0;
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(prog, static_cast<GLuint>(i), max_len + 1, &len, &size, &type, name.data());
        std::string n(name.data(), static_cast<std::size_t>(len));
        if (n.ends_with("[0]")) n.resize(n.size() - 3);
        const GLint loc = glGetUniformLocation(prog, n.c_str());
        if (loc < 0) continue;  // members of uniform blocks
        p.names_.push_back(std::move(n));
        p.locations_.push_back(loc);
    }
    for (std::size_t unit = 0; unit < desc.textures.size(); ++unit)
        glUniform1i(p.location(desc.textures[unit]), static_cast<GLint>(unit));
    for (std::size_t binding = 0; binding < desc.uniform_blocks.size(); ++binding) {
        const GLuint index = glGetUniformBlockIndex(prog, desc.uniform_blocks[binding].c_str());
        if (index != GL_INVALID_INDEX) glUniformBlockBinding(prog, index, static_cast<GLuint>(binding));
    }
    return p;
}

RenderPass Device::begin_pass(const RenderPassDesc& desc) {
    return RenderPass(desc, *extensions_);
}

void Device::read_pixels(const FrameTarget& target, std::span<std::uint8_t> rgba) {
    const int w = target.size.x, h = target.size.y;
    glBindFramebuffer(GL_FRAMEBUFFER,
                      target.texture ? target.texture->framebuffer(target.face, target.level) : 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    // GL's row 0 is the bottom of the picture; files start at the top.
    const std::size_t row = std::size_t(w) * 4;
    for (int y = 0; y < h / 2; ++y)
        std::swap_ranges(rgba.begin() + std::ptrdiff_t(y * row), rgba.begin() + std::ptrdiff_t((y + 1) * row),
                         rgba.begin() + std::ptrdiff_t((h - 1 - y) * row));
}

std::vector<float> Device::read_texture(const Texture& texture, int face) {
    const int w = texture.width(), h = texture.height();
    std::vector<float> out(std::size_t(w) * h * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, texture.framebuffer(face));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    const TextureFormat f = texture.desc().format;
    if (f == TextureFormat::RG32I || f == TextureFormat::RGBA32I) {
        std::vector<GLint> ints(out.size());
        glReadPixels(0, 0, w, h, GL_RGBA_INTEGER, GL_INT, ints.data());
        std::transform(ints.begin(), ints.end(), out.begin(), [](GLint v) { return static_cast<float>(v); });
    } else if (f == TextureFormat::RGBA8 || f == TextureFormat::SRGB8_A8 || f == TextureFormat::R8 ||
               f == TextureFormat::RG8) {  // normalized: GL reads them only as bytes (ES 3.0 §4.3.2)
        std::vector<std::uint8_t> bytes(out.size());
        glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        std::transform(bytes.begin(), bytes.end(), out.begin(), [](std::uint8_t v) { return v / 255.0f; });
    } else {
        glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, out.data());
    }
    return out;
}

void Device::finish() {
    glFinish();
}

std::string Device::take_errors() {
    std::string names;
    // A context can hold one flag per error kind; a lost context repeats GL_CONTEXT_LOST, so stop at 16.
    for (int i = 0; i < 16; ++i) {
        const GLenum e = glGetError();
        if (e == GL_NO_ERROR) break;
        if (!names.empty()) names += ", ";
        names += gl_error_name(e);
    }
    return names;
}

}  // namespace puddle::gpu
