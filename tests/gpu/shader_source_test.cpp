// Shader assembly: #version first, variant #defines, #include spliced with #line so that a driver's
// "FILE:LINE" points back at the right file.
#include "gpu/shader_source.hpp"

#include <gtest/gtest.h>

#include <string>

namespace puddle::gpu {
namespace {

std::string_view fake_files(std::string_view name) {
    if (name == "main.frag")
        return "#version 300 es\nprecision highp float;\n#include \"lib.glsl\"\nvoid main() {}\n";
    if (name == "lib.glsl") return "float f() { return 1.0; }\n";
    if (name == "loop.glsl") return "#include \"loop.glsl\"\n";
    return {};
}

TEST(ShaderSource, VersionComesFirstThenDefinesThenTheFile) {
    const std::string defines[] = {"MAX_DROPS 8", "METHOD_RAYMARCH"};
    auto s = assemble_shader("main.frag", defines, fake_files);
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_TRUE(s->source.starts_with("#version 300 es\n#define MAX_DROPS 8\n#define METHOD_RAYMARCH\n"));
    EXPECT_NE(s->source.find("float f() { return 1.0; }"), std::string::npos);
    EXPECT_EQ(s->source.find("#include"), std::string::npos);
    ASSERT_EQ(s->files.size(), 2u);
    EXPECT_EQ(s->files[0], "main.frag");
    EXPECT_EQ(s->files[1], "lib.glsl");
    // After the include, numbering resumes in main.frag at the line after the #include.
    EXPECT_NE(s->source.find("#line 4 0\nvoid main() {}"), std::string::npos) << s->source;
}

TEST(ShaderSource, DriverMessagesNameTheFile) {
    const std::string none[] = {""};
    auto s = assemble_shader("main.frag", std::span(none, 0), fake_files);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(map_shader_log("1:1(7): error: syntax error\n", *s), "lib.glsl:1: error: syntax error");
    EXPECT_EQ(map_shader_log("ERROR: 0:4: 'x' : undeclared", *s), "ERROR: main.frag:4: 'x' : undeclared");
}

TEST(ShaderSource, MissingFilesAndIncludeLoopsAreErrors) {
    auto missing = assemble_shader("nope.frag", {}, fake_files);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("nope.frag"), std::string::npos);
    auto loop = assemble_shader("loop.glsl", {}, fake_files);
    ASSERT_FALSE(loop.ok());
    EXPECT_NE(loop.error().message.find("nested too deeply"), std::string::npos);
}

TEST(ShaderSource, EveryEmbeddedShaderIsThere) {
    for (const char* name :
         {"fullscreen.vert", "wave_step.frag", "surface.frag", "puddle.frag", "floor.frag"}) {
        auto s = assemble_shader(name, {});
        EXPECT_TRUE(s.ok()) << name;
    }
}

}  // namespace
}  // namespace puddle::gpu
