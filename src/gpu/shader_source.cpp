#include "gpu/shader_source.hpp"

#include <charconv>
#include <regex>

namespace puddle::gpu {

namespace {

std::string_view embedded_lookup(std::string_view name) {
    for (const EmbeddedShader& s : embedded_shaders())
        if (name == s.name) return s.text;
    return {};
}

Result<void> splice(std::string_view name, ShaderLookup lookup, AssembledShader& out, int depth) {
    if (depth > 8) return make_error(ExitCode::Runtime, "shader: {}: includes nested too deeply", name);
    const std::string_view text = lookup(name);
    if (text.empty()) return make_error(ExitCode::Runtime, "shader: {}: no such embedded shader", name);
    const int file = static_cast<int>(out.files.size());
    out.files.emplace_back(name);
    out.source += fmt::format("#line 1 {}\n", file);
    int line = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view l = text.substr(pos, end - pos);
        ++line;
        pos = end + 1;
        if (l.starts_with("#version")) {
            out.source += "\n";  // the assembler writes the one #version line
            continue;
        }
        if (l.starts_with("#include")) {
            const auto q1 = l.find('"'), q2 = l.rfind('"');
            if (q1 == std::string_view::npos || q2 <= q1)
                return make_error(ExitCode::Runtime, "shader: {}:{}: malformed #include", name, line);
            if (auto r = splice(l.substr(q1 + 1, q2 - q1 - 1), lookup, out, depth + 1); !r)
                return make_error(ExitCode::Runtime, "{} (included from {}:{})", r.error().message, name,
                                  line);
            out.source += fmt::format("#line {} {}\n", line + 1, file);
            continue;
        }
        out.source.append(l);
        out.source += '\n';
    }
    return {};
}

}  // namespace

Result<AssembledShader> assemble_shader(std::string_view name, std::span<const std::string> defines,
                                        ShaderLookup lookup) {
    AssembledShader out;
    out.source = "#version 300 es\n";
    for (const std::string& d : defines) out.source += "#define " + d + "\n";
    if (auto r = splice(name, lookup ? lookup : embedded_lookup, out, 0); !r) return r.error();
    return out;
}

std::string map_shader_log(std::string_view log, const AssembledShader& shader) {
    // Mesa writes "0:12(5): error: ...", others "ERROR: 0:12: ...": replace FILE:LINE with name:line.
    static const std::regex pattern(R"((\d+):(\d+)(\(\d+\))?:)");
    std::string out;
    std::string text(log);
    auto begin = std::sregex_iterator(text.begin(), text.end(), pattern);
    std::size_t last = 0;
    for (auto it = begin; it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        int file = 0;
        const std::string num = m[1].str();
        std::from_chars(num.data(), num.data() + num.size(), file);
        out.append(text, last, static_cast<std::size_t>(m.position()) - last);
        if (file >= 0 && file < static_cast<int>(shader.files.size()))
            out += fmt::format("{}:{}:", shader.files[static_cast<std::size_t>(file)], m[2].str());
        else
            out += m.str();
        last = static_cast<std::size_t>(m.position() + m.length());
    }
    out.append(text, last);
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    return out;
}

}  // namespace puddle::gpu
