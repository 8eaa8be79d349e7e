// Tests for src/params/param_types.hpp and Params::get: the enums made from params.def match the
// registry's choices, and typed reads follow every change of value.
#include "params/param_types.hpp"

#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <vector>

#include "params/config_loader.hpp"
#include "params/param_store.hpp"

namespace puddle::params {
namespace {

static_assert(std::is_same_v<decltype(std::declval<const Params&>().get<ParamId::rain_drop_count>()), int>);
static_assert(std::is_same_v<decltype(std::declval<const Params&>().get<ParamId::rain_speed>()), float>);
static_assert(std::is_same_v<decltype(std::declval<const Params&>().get<ParamId::overlay_rain>()), bool>);
static_assert(std::is_same_v<decltype(std::declval<const Params&>().get<ParamId::puddle_size>()), glm::vec3>);
static_assert(
    std::is_same_v<decltype(std::declval<const Params&>().get<ParamId::ground_image>()), const std::string&>);
static_assert(std::is_same_v<decltype(std::declval<const Params&>().get<ParamId::look_tonemap>()), Tonemap>);
static_assert(choice_count<Tonemap> == 4);

template <class E>
std::vector<std::string> names_of() {
    std::vector<std::string> out;
    for (std::string_view n : choice_names<E>()) out.emplace_back(n);
    return out;
}
std::vector<std::string> registry_choices(ParamId id) {
    std::vector<std::string> out;
    for (std::string_view n : decl(id).choices) out.emplace_back(n);
    return out;
}

TEST(ParamTypes, EveryEnumHasTheRegistrysChoicesInOrderAndItsDefault) {
    int enums = 0;
#define PARAM(...)
#define PARAM_ENUM(id, name, Type, def, CHOICES, help)                                                 \
    ++enums;                                                                                           \
    EXPECT_EQ(names_of<Type>(), registry_choices(ParamId::id)) << name;                                \
    EXPECT_EQ(std::get<std::string>(decl(ParamId::id).default_value), choice_name(Type::def)) << name; \
    EXPECT_EQ(Params().get<ParamId::id>(), Type::def) << name;
#include "params/params.def"
    EXPECT_EQ(enums,
              13);  // with wave.model, puddle.shape and ocean.method; wall.mode and wall.clock the last two
}

TEST(ParamTypes, ASpellingThatIsNotAnIdentifierKeepsItsSpelling) {
    EXPECT_EQ(choice_name(DisplayRotation::deg90), "90");
    EXPECT_EQ(choice_name(CameraFormat::automatic), "auto");
    EXPECT_EQ(decl(ParamId::display_rotation).choices.size(), 4u);
}

Params with(std::initializer_list<std::string> sets) {
    Params p;
    for (const std::string& s : sets) {
        auto e = parse_assignment(s);
        EXPECT_TRUE(e.ok()) << s;
        if (e) {
            EXPECT_TRUE(p.set(e->id, e->value, ParamSource::CommandLine));
        }
    }
    return p;
}

TEST(ParamTypes, TypedReadsFollowSetAndReplace) {
    Params p = with({"scene.kind=street", "display.rotation=270", "rain.drop_count=40", "look.tonemap=aces"});
    EXPECT_EQ(p.get<ParamId::scene_kind>(), SceneKind::street);
    EXPECT_EQ(p.get<ParamId::display_rotation>(), DisplayRotation::deg270);
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), 40);
    EXPECT_EQ(p.choice_index(ParamId::look_tonemap), 3);

    p.replace_with(with({"scene.kind=ocean"}));  // everything else back to its default
    EXPECT_EQ(p.get<ParamId::scene_kind>(), SceneKind::ocean);
    EXPECT_EQ(p.get<ParamId::display_rotation>(), DisplayRotation::deg0);
    EXPECT_EQ(p.get<ParamId::look_tonemap>(), Tonemap::soft);
    EXPECT_EQ(p.get<ParamId::rain_drop_count>(), 16);
}

}  // namespace
}  // namespace puddle::params
