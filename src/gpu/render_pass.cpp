#include "gpu/render_pass.hpp"

#include <cassert>
#include <glm/gtc/type_ptr.hpp>

#include "gpu/buffer.hpp"
#include "gpu/gl.hpp"
#include "gpu/gl_debug_labels.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/texture.hpp"

namespace puddle::gpu {

RenderPass::RenderPass(const RenderPassDesc& desc, const GlExtensions& extensions)
    : store_(desc.store), extensions_(&extensions) {
    push_debug_group(*extensions_, desc.label);
    is_default_framebuffer_ = desc.target.texture == nullptr;
    glBindFramebuffer(
        GL_FRAMEBUFFER,
        is_default_framebuffer_ ? 0 : desc.target.texture->framebuffer(desc.target.face, desc.target.level));
    glViewport(0, 0, desc.target.size.x, desc.target.size.y);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    scissored_ = desc.rows.y > 0;
    if (scissored_) {
        assert(desc.load.op != LoadOp::DontCare && "the rows outside the band keep their contents");
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, desc.rows.x, desc.target.size.x, desc.rows.y);
    }
    if (desc.load.op == LoadOp::Clear) {
        glClearColor(desc.clear.r, desc.clear.g, desc.clear.b, desc.clear.a);
        glClear(GL_COLOR_BUFFER_BIT);
    } else if (desc.load.op == LoadOp::DontCare) {
        // Tell a tiler it need not load the old contents: the pass overwrites every pixel.
        const GLenum attachment = is_default_framebuffer_ ? GL_COLOR : GL_COLOR_ATTACHMENT0;
        glInvalidateFramebuffer(GL_FRAMEBUFFER, 1, &attachment);
    }
}

RenderPass& RenderPass::set_pipeline(const Pipeline& pipeline) {
    pipeline_ = &pipeline;
    glUseProgram(pipeline.id());
    if (pipeline.blend() == Blend::Alpha) {
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO,
                            GL_ONE);  // keep the target's alpha
    } else if (pipeline.blend() == Blend::Lit) {
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_DST_COLOR, GL_ONE, GL_ZERO, GL_ONE);
    } else {
        glDisable(GL_BLEND);
    }
    return *this;
}

RenderPass& RenderPass::set_texture(int unit, const Texture& texture, const Sampler& sampler) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    const TextureKind kind = texture.desc().kind;
    glBindTexture(kind == TextureKind::Cube       ? GL_TEXTURE_CUBE_MAP
                  : kind == TextureKind::External ? GL_TEXTURE_EXTERNAL_OES
                                                  : GL_TEXTURE_2D,
                  texture.id());
    glBindSampler(static_cast<GLuint>(unit), sampler.id());
    return *this;
}

RenderPass& RenderPass::set_uniform_buffer(int binding, const Buffer& buffer) {
    glBindBufferBase(GL_UNIFORM_BUFFER, static_cast<GLuint>(binding), buffer.id());
    return *this;
}

RenderPass& RenderPass::set(UniformLocation at, float v) {
    glUniform1f(at.value, v);
    return *this;
}
RenderPass& RenderPass::set(UniformLocation at, int v) {
    glUniform1i(at.value, v);
    return *this;
}
RenderPass& RenderPass::set(UniformLocation at, glm::vec3 v) {
    glUniform3fv(at.value, 1, glm::value_ptr(v));
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, float v) {
    glUniform1f(pipeline_->location(name), v);
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, int v) {
    glUniform1i(pipeline_->location(name), v);
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, glm::vec2 v) {
    glUniform2fv(pipeline_->location(name), 1, glm::value_ptr(v));
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, glm::ivec2 v) {
    glUniform2iv(pipeline_->location(name), 1, glm::value_ptr(v));
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, glm::vec3 v) {
    glUniform3fv(pipeline_->location(name), 1, glm::value_ptr(v));
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, glm::vec4 v) {
    glUniform4fv(pipeline_->location(name), 1, glm::value_ptr(v));
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, const glm::mat3& v) {
    glUniformMatrix3fv(pipeline_->location(name), 1, GL_FALSE, glm::value_ptr(v));
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, std::span<const float> v) {
    glUniform1fv(pipeline_->location(name), static_cast<GLsizei>(v.size()), v.data());
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, std::span<const int> v) {
    glUniform1iv(pipeline_->location(name), static_cast<GLsizei>(v.size()), v.data());
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, std::span<const glm::ivec2> v) {
    glUniform2iv(pipeline_->location(name), static_cast<GLsizei>(v.size()),
                 reinterpret_cast<const GLint*>(v.data()));
    return *this;
}
RenderPass& RenderPass::set(std::string_view name, std::span<const glm::vec4> v) {
    glUniform4fv(pipeline_->location(name), static_cast<GLsizei>(v.size()),
                 reinterpret_cast<const GLfloat*>(v.data()));
    return *this;
}

void RenderPass::draw_fullscreen() {
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void RenderPass::draw_quads(int count) {
    if (count > 0) glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
}

void RenderPass::end() {
    if (ended_) return;
    ended_ = true;
    if (store_ == StoreOp::Discard) {
        const GLenum attachment = is_default_framebuffer_ ? GL_COLOR : GL_COLOR_ATTACHMENT0;
        glInvalidateFramebuffer(GL_FRAMEBUFFER, 1, &attachment);
    }
    if (scissored_) glDisable(GL_SCISSOR_TEST);
    pop_debug_group(*extensions_);
}

}  // namespace puddle::gpu
