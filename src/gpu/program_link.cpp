#include "gpu/program_link.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "gpu/gl.hpp"
#include "gpu/gl_errors.hpp"
#include "gpu/shader_source.hpp"

namespace puddle::gpu {

namespace {

struct ShaderObject {
    GLuint id = 0;
    ~ShaderObject() {
        if (id) glDeleteShader(id);
    }
};

std::string info_log(GLuint object, bool program) {
    GLint length = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
            : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    program ? glGetProgramInfoLog(object, length, nullptr, log.data())
            : glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

Result<void> compile(GLuint shader, const std::string& file, const PipelineDesc& desc) {
    auto assembled = assemble_shader(file, desc.defines);
    if (!assembled)
        return make_error(ExitCode::Runtime, "gpu: {}: {}", desc.label, assembled.error().message);
    const char* text = assembled->source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok)
        return make_error(ExitCode::Runtime, "gpu: pipeline '{}': {}", desc.label,
                          map_shader_log(info_log(shader, false), *assembled));
    return {};
}

}  // namespace

Result<GlHandle<detail::delete_program>> link_program(const PipelineDesc& desc) {
    ShaderObject vs{glCreateShader(GL_VERTEX_SHADER)}, fs{glCreateShader(GL_FRAGMENT_SHADER)};
    // Zero names: the driver could not make the objects (out of memory, or the context is lost).
    if (!vs.id || !fs.id)
        return make_error(ExitCode::Runtime, "gpu: pipeline '{}': glCreateShader: {}", desc.label,
                          gl_error_name(take_gl_error()));
    if (auto r = compile(vs.id, desc.vertex, desc); !r) return r.error();
    if (auto r = compile(fs.id, desc.fragment, desc); !r) return r.error();
    GlHandle<detail::delete_program> program(glCreateProgram());
    const GLuint prog = program.get();
    if (!prog)
        return make_error(ExitCode::Runtime, "gpu: pipeline '{}': glCreateProgram: {}", desc.label,
                          gl_error_name(take_gl_error()));
    glAttachShader(prog, vs.id);
    glAttachShader(prog, fs.id);
    glLinkProgram(prog);
    GLint ok = GL_FALSE;
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok)
        return make_error(ExitCode::Runtime, "gpu: pipeline '{}': link: {}", desc.label,
                          info_log(prog, true));
    return program;
}

}  // namespace puddle::gpu
