// render/shader_hash.hpp against the GLSL it copies (shaders_gles/hash.glsl), on a real context: a probe
// shader that includes hash.glsl writes mix_bits, hash3 and unit_float for a grid of inputs spread over
// the whole 32-bit range into an integer target (RG32I), read back as the exact bits, and each must equal
// the CPU function's. unit_float is compared bit for bit too: float(h >> 8) is exact (under 2^24) and the
// division by 2^24 only changes the exponent, so GLSL ES 3.00's float rules leave no room for rounding.
//
// The probe is compiled here with GL directly: Device::create_pipeline only takes the shaders embedded
// from shaders_gles/, and a test-only shader has no place in the binary.
#include "render/shader_hash.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/device.hpp"
#include "gpu/gl.hpp"
#include "gpu/shader_source.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::render {
namespace {

// u_what 0: (hash3(a, b, c), mix_bits(a)); 1: (unit_float(hash3(a, b, c)) as bits, mix_bits(b)).
constexpr std::string_view kProbe = R"(
precision highp float;
precision highp int;
#include "hash.glsl"
uniform uint u_salt;
uniform int u_what;
layout(location = 0) out ivec4 o_bits;

void main() {
    uvec2 p = uvec2(gl_FragCoord.xy);
    uint a = p.x * 0x9e3779b1u + 0xfffffff0u;
    uint b = p.y * 0x85ebca77u;
    uint h = hash3(a, b, u_salt);
    o_bits = u_what == 0 ? ivec4(int(h), int(mix_bits(a)), 0, 0)
                         : ivec4(floatBitsToInt(unit_float(h)), int(mix_bits(b)), 0, 0);
}
)";

// The same inputs on the CPU.
std::uint32_t input_a(int x) {
    return std::uint32_t(x) * 0x9e3779b1u + 0xfffffff0u;
}
std::uint32_t input_b(int y) {
    return std::uint32_t(y) * 0x85ebca77u;
}

std::string_view probe_lookup(std::string_view name) {
    if (name == "hash_probe.frag") return kProbe;
    for (const gpu::EmbeddedShader& s : gpu::embedded_shaders())
        if (name == s.name) return s.text;
    return {};
}

GLuint compile(GLenum stage, const std::string& source) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        ADD_FAILURE() << log;
    }
    return shader;
}

class ShaderHashTest : public test::DeviceFixture {
protected:
    static constexpr int kWidth = 64, kHeight = 32;

    void SetUp() override {
        test::DeviceFixture::SetUp();
        if (HasFatalFailure()) return;
        auto vertex = gpu::assemble_shader("fullscreen.vert", {});
        auto fragment = gpu::assemble_shader("hash_probe.frag", {}, probe_lookup);
        ASSERT_TRUE(vertex.ok() && fragment.ok());
        const GLuint vs = compile(GL_VERTEX_SHADER, vertex->source);
        const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment->source);
        program_ = glCreateProgram();
        glAttachShader(program_, vs);
        glAttachShader(program_, fs);
        glLinkProgram(program_);
        glDeleteShader(vs);
        glDeleteShader(fs);
        GLint linked = 0;
        glGetProgramiv(program_, GL_LINK_STATUS, &linked);
        ASSERT_TRUE(linked);
        auto target = device_->create_texture({.label = "hash bits",
                                               .format = gpu::TextureFormat::RG32I,
                                               .width = kWidth,
                                               .height = kHeight,
                                               .render_target = true});
        ASSERT_TRUE(target.ok()) << target.error().message;
        target_ = std::move(target).value();
    }
    void TearDown() override {
        glDeleteProgram(program_);
        target_ = {};
        test::DeviceFixture::TearDown();
    }

    // The probe's two outputs per pixel, rows in GL order (row 0 at y = 0).
    std::vector<std::uint32_t> draw(std::uint32_t salt, int what) {
        glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer());
        glViewport(0, 0, kWidth, kHeight);
        glUseProgram(program_);
        glUniform1ui(glGetUniformLocation(program_, "u_salt"), salt);
        glUniform1i(glGetUniformLocation(program_, "u_what"), what);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        std::vector<GLint> rgba(std::size_t(kWidth) * kHeight * 4);
        glReadPixels(0, 0, kWidth, kHeight, GL_RGBA_INTEGER, GL_INT, rgba.data());
        EXPECT_EQ(device_->take_errors(), "");
        std::vector<std::uint32_t> bits;
        for (std::size_t i = 0; i < rgba.size(); i += 4) {
            bits.push_back(std::bit_cast<std::uint32_t>(rgba[i]));
            bits.push_back(std::bit_cast<std::uint32_t>(rgba[i + 1]));
        }
        return bits;
    }

    GLuint program_ = 0;
    gpu::Texture target_;
};

TEST_F(ShaderHashTest, Hash3AndMixBitsMatchTheGlslBitForBit) {
    for (const std::uint32_t salt : {0u, 7u, 0x9e3779b9u, 0xffffffffu}) {
        const std::vector<std::uint32_t> gpu = draw(salt, 0);
        int mismatches = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const std::size_t i = (std::size_t(y) * kWidth + x) * 2;
                const std::uint32_t hash = shader_hash3(input_a(x), input_b(y), salt);
                if (gpu[i] != hash || gpu[i + 1] != shader_mix_bits(input_a(x)))
                    ADD_FAILURE() << "salt " << salt << " at (" << x << ", " << y << "): GLSL hash3 "
                                  << gpu[i] << ", CPU " << hash << "; GLSL mix_bits " << gpu[i + 1]
                                  << ", CPU " << shader_mix_bits(input_a(x))
                                  << (++mismatches > 5 ? " (stopping)" : "");
                if (mismatches > 5) return;
            }
    }
}

TEST_F(ShaderHashTest, UnitFloatMatchesTheGlslExactly) {
    const std::uint32_t salt = 12345u;
    const std::vector<std::uint32_t> gpu = draw(salt, 1);
    int mismatches = 0;
    for (int y = 0; y < kHeight && mismatches <= 5; ++y)
        for (int x = 0; x < kWidth && mismatches <= 5; ++x) {
            const std::size_t i = (std::size_t(y) * kWidth + x) * 2;
            const double cpu = shader_unit_float(shader_hash3(input_a(x), input_b(y), salt));
            const float glsl = std::bit_cast<float>(gpu[i]);
            EXPECT_GE(cpu, 0.0);
            EXPECT_LT(cpu, 1.0);
            if (static_cast<double>(glsl) != cpu || gpu[i + 1] != shader_mix_bits(input_b(y))) {
                ++mismatches;
                ADD_FAILURE() << "at (" << x << ", " << y << "): GLSL unit_float " << glsl << ", CPU " << cpu;
            }
        }
}

}  // namespace
}  // namespace puddle::render
