#include "render/puddle_variant.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "params/registry.hpp"

namespace puddle::render {

using params::ParamId;

namespace {

// The brightest ground any kind can show, before the water's filter: an image darkened to 60%.
constexpr float brightest_ground = 0.6f;
constexpr float hidden_below = 1.0f / 4096.0f;
// The raymarch bounds the displacement by four times the height scale; the same bound here.
constexpr float bound = 4.0f;

}  // namespace

bool ground_hidden(const params::Params& params) {
    // The ground plane is at y = -depth; the lowest trough of the water top is the nearest point to it.
    const float trough =
        0.5f * params.get<ParamId::puddle_size>().y - bound * params.get<ParamId::wave_height_scale>();
    const float shortest = std::max(trough + params.get<ParamId::puddle_depth>(), 0.0f);
    return brightest_ground * std::exp(-params.get<ParamId::water_turbidity>() * shortest) < hidden_below;
}

PuddleVariant choose_puddle_variant(const params::Params& params, bool env_rgbm, bool cloud_layer) {
    PuddleVariant v;
    v.raymarch = params.get<ParamId::render_method>() == params::RenderMethod::raymarch;
    v.shore = !v.raymarch && params.get<ParamId::puddle_shape>() == params::PuddleShape::shore;
    // Beside a shore the ground shows whatever the water hides.
    v.ground = (ground_hidden(params) && !v.shore)           ? GroundKind::Hidden
               : params.get<ParamId::ground_checkerboard>()  ? GroundKind::Checkerboard
               : params.get<ParamId::ground_image>().empty() ? GroundKind::Paving
                                                             : GroundKind::Image;
    v.env_rgbm = env_rgbm;
    v.cloud_layer = cloud_layer && !env_rgbm;
    v.tonemap = params.get<ParamId::look_tonemap>();
    return v;
}

std::size_t variant_index(const PuddleVariant& v) {
    std::size_t i = v.raymarch ? 1 : 0;
    i = i * 2 + (v.shore ? 1 : 0);
    i = i * ground_kind_count + static_cast<std::size_t>(v.ground);
    i = i * 2 + (v.env_rgbm ? 1 : 0);
    i = i * 2 + (v.cloud_layer ? 1 : 0);
    return i * tonemap_count + static_cast<std::size_t>(v.tonemap);
}

std::vector<std::string> variant_defines(const PuddleVariant& v, bool surface_unorm) {
    std::vector<std::string> d;
    if (surface_unorm) d.emplace_back("SURFACE_UNORM");
    if (v.raymarch) d.emplace_back("METHOD_RAYMARCH");
    if (v.shore) d.emplace_back("SHORE");
    if (v.ground == GroundKind::Paving) d.emplace_back("GROUND_PAVING");
    if (v.ground == GroundKind::Image) d.emplace_back("GROUND_IMAGE");
    if (v.ground == GroundKind::Hidden) d.emplace_back("GROUND_HIDDEN");
    if (v.env_rgbm) d.emplace_back("ENV_RGBM");
    if (v.cloud_layer) d.emplace_back("CLOUD_LAYER");
    d.push_back(fmt::format("TONEMAP {}", static_cast<int>(v.tonemap)));
    return d;
}

std::string describe(const PuddleVariant& v) {
    static constexpr const char* grounds[] = {"checkerboard", "paving", "ground image", "ground hidden"};
    return fmt::format("{}{}, {}{}{}, {} tone curve", v.raymarch ? "raymarch" : "intersect",
                       v.shore ? ", shore" : "", grounds[static_cast<int>(v.ground)],
                       v.env_rgbm ? ", RGBM sky" : "", v.cloud_layer ? ", drifting clouds" : "",
                       params::choice_name(v.tonemap));
}

}  // namespace puddle::render
