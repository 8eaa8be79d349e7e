#include "systems/puddle_variant.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "params/registry.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {

int choice_index(const params::Params& params, ParamId id) {
    const auto& choices = params::decl(id).choices;
    const auto it = std::find(choices.begin(), choices.end(), params.s(id));
    return it == choices.end() ? 0 : static_cast<int>(it - choices.begin());
}

// The brightest ground either kind can show, before the water's filter: an image darkened to 60%.
constexpr float brightest_ground = 0.6f;
constexpr float hidden_below = 1.0f / 4096.0f;
// The raymarch bounds the displacement by four times the height scale; the same bound here.
constexpr float bound = 4.0f;

}  // namespace

bool ground_hidden(const params::Params& params) {
    // The ground plane is at y = -depth; the lowest trough of the water top is the nearest point to it.
    const float trough = 0.5f * params.v3(ParamId::puddle_size).y - bound * params.f(ParamId::wave_height_scale);
    const float shortest = std::max(trough + params.f(ParamId::puddle_depth), 0.0f);
    return brightest_ground * std::exp(-params.f(ParamId::water_turbidity) * shortest) < hidden_below;
}

PuddleVariant choose_puddle_variant(const params::Params& params, bool env_rgbm) {
    PuddleVariant v;
    v.raymarch = params.s(ParamId::render_method) == "raymarch";
    v.ground = ground_hidden(params)                   ? GroundKind::Hidden
               : params.b(ParamId::ground_checkerboard) ? GroundKind::Checkerboard
                                                        : GroundKind::Image;
    v.env_rgbm = env_rgbm;
    v.tonemap = std::clamp(choice_index(params, ParamId::look_tonemap), 0, static_cast<int>(tonemap_count) - 1);
    return v;
}

std::size_t variant_index(const PuddleVariant& v) {
    std::size_t i = v.raymarch ? 1 : 0;
    i = i * 3 + static_cast<std::size_t>(v.ground);
    i = i * 2 + (v.env_rgbm ? 1 : 0);
    return i * tonemap_count + static_cast<std::size_t>(v.tonemap);
}

std::vector<std::string> variant_defines(const PuddleVariant& v, bool surface_unorm) {
    std::vector<std::string> d;
    if (surface_unorm) d.emplace_back("SURFACE_UNORM");
    if (v.raymarch) d.emplace_back("METHOD_RAYMARCH");
    if (v.ground == GroundKind::Image) d.emplace_back("GROUND_IMAGE");
    if (v.ground == GroundKind::Hidden) d.emplace_back("GROUND_HIDDEN");
    if (v.env_rgbm) d.emplace_back("ENV_RGBM");
    d.push_back(fmt::format("TONEMAP {}", v.tonemap));
    return d;
}

std::string describe(const PuddleVariant& v) {
    static constexpr const char* grounds[] = {"checkerboard", "ground image", "ground hidden"};
    const auto& tonemaps = params::decl(ParamId::look_tonemap).choices;
    return fmt::format("{}, {}{}, {} tone curve", v.raymarch ? "raymarch" : "intersect",
                       grounds[static_cast<int>(v.ground)], v.env_rgbm ? ", RGBM sky" : "",
                       tonemaps[static_cast<std::size_t>(v.tonemap)]);
}

}  // namespace puddle::systems
