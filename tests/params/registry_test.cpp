// Tests for src/params/registry.hpp: the declarations, parsing and range messages. The precedence rules
// of Params: param_store_test.cpp.
#include "params/registry.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <stdexcept>
#include <string>

namespace puddle::params {
namespace {

bool is_name_part(std::string_view s) {
    if (s.empty() || !std::islower(static_cast<unsigned char>(s.front()))) return false;
    for (char c : s)
        if (!(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) ||
              c == '_'))
            return false;
    return true;
}

const ParamDecl& must_find(std::string_view name) {
    const ParamDecl* d = find_param(name);
    if (!d) throw std::runtime_error("missing parameter " + std::string(name));
    return *d;
}

// parse_value's error message, or "<ok>" when it parsed.
std::string parse_error(std::string_view name, std::string_view text) {
    auto r = parse_value(must_find(name), text);
    if (r) return "<ok>";
    EXPECT_EQ(r.error().code, ExitCode::Config) << r.error().message;
    return r.error().message;
}

template <class T>
T parsed(std::string_view name, std::string_view text) {
    auto r = parse_value(must_find(name), text);
    if (!r) {
        ADD_FAILURE() << name << " = " << text << ": " << r.error().message;
        return T{};
    }
    return std::get<T>(*r);
}

TEST(Registry, TableMatchesParamIdOrder) {
    ASSERT_EQ(param_decls().size(), param_count);
    for (std::size_t i = 0; i < param_count; ++i) {
        const ParamDecl& d = param_decls()[i];
        EXPECT_EQ(static_cast<std::size_t>(d.id), i) << d.name;
        EXPECT_EQ(&decl(d.id), &d) << d.name;
        EXPECT_EQ(find_param(d.name), &d) << d.name;
    }
}

TEST(Registry, EveryDeclarationIsWellFormed) {
    std::set<std::string_view> names, uniforms;
    for (const ParamDecl& d : param_decls()) {
        SCOPED_TRACE(std::string(d.name));
        EXPECT_TRUE(names.insert(d.name).second) << "duplicate name";
        const auto dot = d.name.find('.');
        ASSERT_NE(dot, std::string_view::npos) << "not section.key";
        EXPECT_EQ(d.name.find('.', dot + 1), std::string_view::npos) << "more than one dot";
        EXPECT_TRUE(is_name_part(d.name.substr(0, dot))) << "bad section";
        EXPECT_TRUE(is_name_part(d.name.substr(dot + 1))) << "bad key";
        EXPECT_FALSE(d.help.empty());
        EXPECT_TRUE(validate(d, d.default_value).ok()) << validate(d, d.default_value).error().message;
        EXPECT_TRUE(uniforms.insert(d.uniform).second) << "duplicate uniform";
        if (d.kind == ParamKind::Enum) {
            EXPECT_GE(d.choices.size(), 2u);
        } else {
            EXPECT_TRUE(d.choices.empty());
        }
        if (d.kind == ParamKind::Int || d.kind == ParamKind::Float || d.kind == ParamKind::Vec3 ||
            d.kind == ParamKind::Color) {
            EXPECT_LT(d.min, d.max);
        }
    }
}

TEST(Registry, ReferenceParametersExistWithTheirKinds) {
    const std::pair<std::string_view, ParamKind> expected[] = {
        {"rain.drop_count", ParamKind::Int},
        {"rain.intensity", ParamKind::Float},
        {"rain.speed", ParamKind::Float},
        {"wave.damping", ParamKind::Float},
        {"water.reflectivity", ParamKind::Float},
        {"look.vignette", ParamKind::Float},
        {"look.fog_density", ParamKind::Float},
        {"environment.rotation", ParamKind::Float},
        {"ground.checkerboard", ParamKind::Bool},
        {"ground.scale", ParamKind::Float},
        {"water.turbidity", ParamKind::Float},
        {"puddle.depth", ParamKind::Float},
        {"water.tint", ParamKind::Color},
        {"camera.position", ParamKind::Vec3},
        {"camera.target", ParamKind::Vec3},
        {"camera.fov", ParamKind::Float},
        {"puddle.size", ParamKind::Vec3},
        {"wave.resolution", ParamKind::Int},
        {"wave.steps_per_second", ParamKind::Float},
        {"water.normal_strength", ParamKind::Float},
        {"rain.seed", ParamKind::Int},
        {"environment.image", ParamKind::Path},
        {"render.method", ParamKind::Enum},
    };
    for (const auto& [name, kind] : expected) {
        const ParamDecl* d = find_param(name);
        ASSERT_NE(d, nullptr) << name;
        EXPECT_EQ(d->kind, kind) << name;
    }
    EXPECT_EQ(find_param("rain.nope"), nullptr);
    EXPECT_EQ(find_param("rain"), nullptr);
    EXPECT_EQ(find_param(""), nullptr);
}

// Ranges and fixed defaults (the look's defaults are tuned, so they are checked only against validate()).
TEST(Registry, SomeDefaultsAndRanges) {
    const ParamDecl& drops = decl(ParamId::rain_drop_count);
    EXPECT_EQ(drops.name, "rain.drop_count");
    EXPECT_EQ(drops.min, 1);
    EXPECT_EQ(drops.max, 128);
    EXPECT_EQ(drops.unit, "drops");
    EXPECT_EQ(std::get<float>(decl(ParamId::wave_steps_per_second).default_value), 60.0f);
    EXPECT_EQ(std::get<int>(decl(ParamId::rain_seed).default_value), 1);
    EXPECT_EQ(std::get<std::string>(decl(ParamId::environment_image).default_value), "");
    EXPECT_EQ(std::get<std::string>(decl(ParamId::render_method).default_value), "intersect");
    ASSERT_EQ(decl(ParamId::render_method).choices.size(), 2u);
    EXPECT_EQ(decl(ParamId::render_method).choices[0], "intersect");
    EXPECT_EQ(decl(ParamId::render_method).choices[1], "raymarch");
}

TEST(Registry, UniformNamesAreUSectionKey) {
    EXPECT_EQ(decl(ParamId::rain_drop_count).uniform, "u_rain_drop_count");
    EXPECT_EQ(decl(ParamId::water_tint).uniform, "u_water_tint");
    EXPECT_EQ(decl(ParamId::wave_steps_per_second).uniform, "u_wave_steps_per_second");
    EXPECT_EQ(decl(ParamId::camera_fov).uniform, "u_camera_fov");
    for (const ParamDecl& d : param_decls()) {
        std::string expected = "u_" + std::string(d.name);
        expected[expected.find('.')] = '_';
        EXPECT_EQ(d.uniform, expected);
    }
}

// A hint reads only the first hint_name_limit characters, so its cost does not grow with the name (a
// 41 KB knob param made the state fuzzer time out, and a live config edit would stall the frame thread).
TEST(Registry, NearestParamNameReadsOnlyTheNamesStart) {
    const std::string start(hint_name_limit, 'z');
    EXPECT_EQ(nearest_param_name(start + "rain.drop_count"), nearest_param_name(start));
    EXPECT_NE(nearest_param_name(start), "rain.drop_count");  // so the tail would have changed the hint
    EXPECT_EQ(nearest_param_name("rain.drop_cont" + std::string(100000, 'a')), "rain.drop_count");
}

TEST(Registry, NearestParamNameFindsTypos) {
    EXPECT_EQ(nearest_param_name("rain.drop_cont"), "rain.drop_count");
    EXPECT_EQ(nearest_param_name("rain.dropcount"), "rain.drop_count");
    EXPECT_EQ(nearest_param_name("drop_count"), "rain.drop_count");  // the section left out
    EXPECT_EQ(nearest_param_name("drop_cont"), "rain.drop_count");
    EXPECT_EQ(nearest_param_name("wave.dampning"), "wave.damping");
    EXPECT_EQ(nearest_param_name("water.turbidty"), "water.turbidity");
    EXPECT_EQ(nearest_param_name("rain.intesity"), "rain.intensity");
    EXPECT_EQ(nearest_param_name("look.vingette"), "look.vignette");
    EXPECT_EQ(nearest_param_name("water.tint"), "water.tint");  // an exact name is its own nearest
}

TEST(Registry, KindNames) {
    EXPECT_EQ(kind_name(ParamKind::Bool), "bool");
    EXPECT_EQ(kind_name(ParamKind::Int), "int");
    EXPECT_EQ(kind_name(ParamKind::Float), "float");
    EXPECT_EQ(kind_name(ParamKind::Vec3), "vec3");
    EXPECT_EQ(kind_name(ParamKind::Color), "color");
    EXPECT_EQ(kind_name(ParamKind::Enum), "enum");
    EXPECT_EQ(kind_name(ParamKind::Path), "text");
}

TEST(Registry, DescribeRangeWording) {
    EXPECT_EQ(describe_range(decl(ParamId::ground_checkerboard)), "true or false");
    EXPECT_EQ(describe_range(decl(ParamId::rain_drop_count)), "an integer from 1 to 128 drops");
    EXPECT_EQ(describe_range(decl(ParamId::rain_seed)), "an integer from 0 to 2147483647");
    EXPECT_EQ(describe_range(decl(ParamId::rain_intensity)), "a number from 0 to 4 height");
    EXPECT_EQ(describe_range(decl(ParamId::wave_damping)), "a number from 0.9 to 1");
    EXPECT_EQ(describe_range(decl(ParamId::ground_scale)), "a number from 0.01 to 10 tiles/unit");
    EXPECT_EQ(describe_range(decl(ParamId::environment_rotation)), "a number from 0 to 6.28319 rad");
    EXPECT_EQ(describe_range(decl(ParamId::camera_position)),
              "three numbers [x, y, z], each from -1000 to 1000 units");
    EXPECT_EQ(describe_range(decl(ParamId::water_tint)), "three numbers [x, y, z], each from 0 to 1 rgb");
    EXPECT_EQ(describe_range(decl(ParamId::render_method)), "one of: intersect, raymarch");
    EXPECT_EQ(describe_range(decl(ParamId::environment_image)), "text (path)");
}

TEST(Registry, FormatValue) {
    EXPECT_EQ(format_value(true), "true");
    EXPECT_EQ(format_value(false), "false");
    EXPECT_EQ(format_value(42), "42");
    EXPECT_EQ(format_value(0.25f), "0.25");
    EXPECT_EQ(format_value(glm::vec3(1.0f, 0.5f, -2.0f)), "[1, 0.5, -2]");
    EXPECT_EQ(format_value(std::string("a b")), "\"a b\"");
}

TEST(ParseValue, Bool) {
    for (const char* t : {"true", "1", "on", "yes", " true "})
        EXPECT_TRUE(parsed<bool>("ground.checkerboard", t)) << t;
    for (const char* t : {"false", "0", "off", "no"})
        EXPECT_FALSE(parsed<bool>("ground.checkerboard", t)) << t;
    EXPECT_EQ(parse_error("ground.checkerboard", "maybe"),
              "ground.checkerboard = \"maybe\" is not valid: expected true or false");
    EXPECT_EQ(parse_error("ground.checkerboard", ""),
              "ground.checkerboard = \"\" is not valid: expected true or false");
}

TEST(ParseValue, Int) {
    EXPECT_EQ(parsed<int>("rain.drop_count", "20"), 20);
    EXPECT_EQ(parsed<int>("rain.drop_count", "+7"), 7);
    EXPECT_EQ(parsed<int>("rain.drop_count", " 1 "), 1);
    EXPECT_EQ(parsed<int>("rain.drop_count", "128"), 128);
    EXPECT_EQ(parse_error("rain.drop_count", "129"),
              "rain.drop_count = 129 is out of range: allowed an integer from 1 to 128 drops");
    EXPECT_EQ(parse_error("rain.drop_count", "0"),
              "rain.drop_count = 0 is out of range: allowed an integer from 1 to 128 drops");
    EXPECT_EQ(parse_error("rain.drop_count", "-3"),
              "rain.drop_count = -3 is out of range: allowed an integer from 1 to 128 drops");
    EXPECT_EQ(parse_error("rain.drop_count", "ten"),
              "rain.drop_count = \"ten\" is not valid: expected an integer from 1 to 128 drops");
    EXPECT_EQ(parse_error("rain.drop_count", "2.5"),
              "rain.drop_count = \"2.5\" is not valid: expected an integer from 1 to 128 drops");
    EXPECT_EQ(parse_error("rain.drop_count", "12abc"),
              "rain.drop_count = \"12abc\" is not valid: expected an integer from 1 to 128 drops");
    EXPECT_EQ(parse_error("rain.drop_count", ""),
              "rain.drop_count = \"\" is not valid: expected an integer from 1 to 128 drops");
    EXPECT_EQ(parsed<int>("rain.seed", "2147483647"), 2147483647);
    EXPECT_NE(parse_error("rain.seed", "2147483648"), "<ok>");  // does not fit an int
}

TEST(ParseValue, Float) {
    EXPECT_EQ(parsed<float>("rain.intensity", "0.5"), 0.5f);
    EXPECT_EQ(parsed<float>("rain.intensity", "2"), 2.0f);
    EXPECT_EQ(parsed<float>("rain.intensity", "1e-1"), 0.1f);
    EXPECT_EQ(parsed<float>("wave.damping", "1"), 1.0f);  // the bounds are inclusive
    EXPECT_EQ(parsed<float>("wave.damping", "0.9"), 0.9f);
    EXPECT_EQ(parse_error("rain.intensity", "5"),
              "rain.intensity = 5 is out of range: allowed a number from 0 to 4 height");
    EXPECT_EQ(parse_error("wave.damping", "0.5"),
              "wave.damping = 0.5 is out of range: allowed a number from 0.9 to 1");
    EXPECT_EQ(parse_error("wave.damping", "1.01"),
              "wave.damping = 1.01 is out of range: allowed a number from 0.9 to 1");
    EXPECT_EQ(parse_error("rain.intensity", "lots"),
              "rain.intensity = \"lots\" is not valid: expected a number from 0 to 4 height");
    EXPECT_EQ(parse_error("rain.intensity", "nan"),
              "rain.intensity = nan is out of range: allowed a number from 0 to 4 height");
    EXPECT_NE(parse_error("rain.intensity", "inf"), "<ok>");
}

TEST(ParseValue, Vec3AndColor) {
    EXPECT_EQ(parsed<glm::vec3>("camera.position", "1,2,3"), glm::vec3(1, 2, 3));
    EXPECT_EQ(parsed<glm::vec3>("camera.position", "[1, -2.5, 3]"), glm::vec3(1, -2.5f, 3));
    EXPECT_EQ(parsed<glm::vec3>("water.tint", "0.1, 0.2, 0.3"), glm::vec3(0.1f, 0.2f, 0.3f));
    const std::string camera_allowed = "three numbers [x, y, z], each from -1000 to 1000 units";
    EXPECT_EQ(parse_error("camera.position", "1,2"),
              "camera.position = \"1,2\" is not valid: expected " + camera_allowed);
    EXPECT_EQ(parse_error("camera.position", "1,2,3,4"),
              "camera.position = \"1,2,3,4\" is not valid: expected " + camera_allowed);
    EXPECT_EQ(parse_error("camera.position", "1,x,3"),
              "camera.position = \"1,x,3\" is not valid: expected " + camera_allowed);
    EXPECT_EQ(parse_error("camera.position", "2000,0,0"),
              "camera.position = [2000, 0, 0] is out of range: allowed " + camera_allowed);
    EXPECT_EQ(
        parse_error("water.tint", "0.5,1.5,0"),
        "water.tint = [0.5, 1.5, 0] is out of range: allowed three numbers [x, y, z], each from 0 to 1 rgb");
    EXPECT_EQ(parse_error("puddle.size", "0,10,10"),
              "puddle.size = [0, 10, 10] is out of range: allowed three numbers [x, y, z], each from 1 to "
              "1000 units");
}

TEST(ParseValue, EnumAndPath) {
    EXPECT_EQ(parsed<std::string>("render.method", "raymarch"), "raymarch");
    EXPECT_EQ(parsed<std::string>("render.method", " intersect "), "intersect");
    EXPECT_EQ(parse_error("render.method", "fast"),
              "render.method = \"fast\" is not allowed: one of: intersect, raymarch");
    EXPECT_EQ(parse_error("render.method", "Raymarch"),
              "render.method = \"Raymarch\" is not allowed: one of: intersect, raymarch");
    EXPECT_EQ(parsed<std::string>("environment.image", " /usr/share/puddle/sky "), "/usr/share/puddle/sky");
    EXPECT_EQ(parsed<std::string>("ground.image", ""), "");
}

TEST(Validate, WrongKindIsRejected) {
    auto r = validate(decl(ParamId::rain_drop_count), ParamValue(2.0f));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ExitCode::Config);
    EXPECT_EQ(r.error().message,
              "rain.drop_count = 2 has the wrong type: expected an integer from 1 to 128 drops");
    auto b = validate(decl(ParamId::ground_checkerboard), ParamValue(1));
    ASSERT_FALSE(b);
    EXPECT_EQ(b.error().message, "ground.checkerboard = 1 has the wrong type: expected true or false");
    EXPECT_FALSE(validate(decl(ParamId::water_tint), ParamValue(std::string("red"))));
    EXPECT_FALSE(validate(decl(ParamId::environment_image), ParamValue(true)));
    EXPECT_TRUE(validate(decl(ParamId::water_tint), ParamValue(glm::vec3(0, 1, 0.5f))));
}

}  // namespace
}  // namespace puddle::params
