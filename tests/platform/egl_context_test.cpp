// Tests for src/platform/egl_context.hpp on Mesa's surfaceless platform: a GLES 3 context made current
// with no surface, a move that hands the context over, has_extension matching whole words of the
// display's list, and a worker context that shares objects with the one that made it (a texture made
// on either context is read back on the other, from another thread as the pipeline compiler does).
#include "platform/egl_context.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "gpu/gl.hpp"

namespace puddle::platform {
namespace {

Result<EglContext> surfaceless() {
    return EglContext::create(
        {.platform = EGL_PLATFORM_SURFACELESS_MESA, .native_display = EGL_DEFAULT_DISPLAY});
}

using Texel = std::array<std::uint8_t, 4>;
const std::vector<Texel> texels = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {7, 77, 177, 255}};
// Different texels for the worker's texture: its name may equal one made here, were the names not shared.
const std::vector<Texel> worker_texels = {
    {1, 2, 3, 255}, {40, 50, 60, 255}, {200, 100, 0, 255}, {9, 9, 9, 255}};

// A 2x2 RGBA8 texture holding `content` on the current context; glFinish so that another context sees it.
GLuint make_texture(const std::vector<Texel>& content) {
    GLuint id = 0;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, content.data());
    glFinish();
    return id;
}

// The texture's texels read on the current context through a framebuffer of its own (framebuffers are
// not shared); empty when the name is no texture here.
std::vector<Texel> read_texture(GLuint id) {
    if (!glIsTexture(id)) return {};
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, id, 0);
    std::vector<Texel> out;
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) {
        out.resize(4);
        glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    return out;
}

TEST(EglContext, ASurfacelessContextIsCurrentGles3) {
    auto ctx = surfaceless();
    ASSERT_TRUE(ctx.ok()) << ctx.error().message;
    ASSERT_TRUE(ctx->make_current_surfaceless().ok());
    EXPECT_EQ(eglGetCurrentContext(), ctx->context());
    EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), EGL_NO_SURFACE);
    GLint major = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    EXPECT_GE(major, 3);
    EXPECT_EQ(ctx->vendor(), std::string(eglQueryString(ctx->display(), EGL_VENDOR)));
}

TEST(EglContext, AMoveHandsTheContextOverAndTheEndReleasesIt) {
    auto made = surfaceless();
    ASSERT_TRUE(made.ok()) << made.error().message;
    EglContext first = std::move(made).value();
    const EGLContext context = first.context();
    EglContext second = std::move(first);
    EXPECT_EQ(first.display(), EGL_NO_DISPLAY);  // NOLINT(bugprone-use-after-move): what a move leaves
    EXPECT_EQ(first.context(), EGL_NO_CONTEXT);
    EXPECT_EQ(second.context(), context);
    ASSERT_TRUE(second.make_current_surfaceless().ok());
    EXPECT_EQ(eglGetCurrentContext(), context);
    { EglContext gone = std::move(second); }
    EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT) << "a context that ends is no longer current";
}

TEST(EglContext, HasExtensionMatchesWholeWordsOfTheDisplaysList) {
    auto ctx = surfaceless();
    ASSERT_TRUE(ctx.ok()) << ctx.error().message;
    std::istringstream list(eglQueryString(ctx->display(), EGL_EXTENSIONS));
    std::set<std::string> words;
    for (std::string w; list >> w;) words.insert(w);
    ASSERT_GE(words.size(), 2u);
    for (const std::string& w : words) {
        EXPECT_TRUE(ctx->has_extension(w)) << w;
        // A word's head or tail, or the word run on, is a different name unless the list holds it too.
        for (const std::string& part : {w.substr(0, w.size() - 1), w.substr(1), w + "_2"})
            EXPECT_EQ(ctx->has_extension(part), words.count(part) == 1) << part;
    }
    EXPECT_FALSE(ctx->has_extension("EGL_PUDDLE_no_such_extension"));
    EXPECT_FALSE(ctx->has_extension("")) << "an empty name is no extension (and ends the search)";
}

TEST(EglContext, AWorkerContextSharesObjectsBothWays) {
    auto ctx = surfaceless();
    ASSERT_TRUE(ctx.ok()) << ctx.error().message;
    ASSERT_TRUE(ctx->make_current_surfaceless().ok());
    auto worker = ctx->create_worker_context();
    if (!worker.ok() && !ctx->has_extension("EGL_KHR_surfaceless_context"))
        GTEST_SKIP() << worker.error().message;
    ASSERT_TRUE(worker.ok()) << worker.error().message;

    const GLuint made_here = make_texture(texels);
    std::vector<Texel> read_there;
    GLuint made_there = 0;
    std::string worker_error;
    std::thread([&] {
        if (auto current = (*worker)->make_current(); !current.ok()) {
            worker_error = current.error().message;
            return;
        }
        read_there = read_texture(made_here);
        made_there = make_texture(worker_texels);
        (*worker)->release();
    }).join();
    ASSERT_EQ(worker_error, "");
    EXPECT_EQ(read_there, texels) << "a texture made here, read on the worker";
    EXPECT_EQ(read_texture(made_there), worker_texels) << "a texture made on the worker, read here";
    glDeleteTextures(1, &made_here);
    glDeleteTextures(1, &made_there);
}

}  // namespace
}  // namespace puddle::platform
