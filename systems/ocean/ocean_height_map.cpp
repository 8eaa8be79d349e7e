#include "systems/ocean/ocean_height_map.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <optional>

namespace puddle::systems {

float ocean_highest_wave(float height, int octaves) {
    float sum = 0, amplitude = height;
    for (int i = 0; i < octaves; ++i, amplitude *= 0.22f) sum += 2.0f * amplitude;
    return sum;
}

float ocean_height_map_min_eye(float highest_wave) {
    return 1.25f * highest_wave + 0.05f;
}

namespace {

// The view direction through view uv `uv` (not normalized), as ocean.frag makes it.
glm::vec3 ray_through(const render::ViewBasis& view, glm::vec2 uv) {
    const glm::vec2 ndc = uv * 2.0f - 1.0f;
    return view.forward + ndc.x * view.scale.x * view.right + ndc.y * view.scale.y * view.up;
}

// Where the eye sees world point q in the view's uv; nothing for a point beside or behind the eye.
std::optional<glm::vec2> view_uv_of(const render::ViewBasis& view, glm::vec3 eye, glm::vec3 q) {
    const glm::vec3 d = q - eye;
    const float z = glm::dot(d, view.forward);
    if (z <= 1e-4f) return std::nullopt;
    const glm::vec2 ndc{glm::dot(d, view.right) / (z * view.scale.x),
                        glm::dot(d, view.up) / (z * view.scale.y)};
    return ndc * 0.5f + 0.5f;
}

}  // namespace

OceanHeightMapLayout ocean_height_map_layout(const render::ViewBasis& view, glm::vec3 eye, float highest_wave,
                                             const render::ViewWindow& window, glm::ivec2 target_size) {
    OceanHeightMapLayout layout;
    layout.plane = highest_wave;
    if (eye.y < ocean_height_map_min_eye(highest_wave) || target_size.x <= 0 || target_size.y <= 0)
        return layout;
    constexpr int samples = 17;
    const glm::vec2 spacing = window.extent / float(samples - 1);
    glm::vec2 low{0}, high{0};
    bool any = false;
    auto include = [&](glm::vec2 uv) {
        low = any ? glm::min(low, uv) : uv;
        high = any ? glm::max(high, uv) : uv;
        any = true;
    };
    for (int j = 0; j < samples; ++j)
        for (int i = 0; i < samples; ++i) {
            const glm::vec2 uv = window.origin + glm::vec2(i, j) * spacing;
            const glm::vec3 dir = glm::normalize(ray_through(view, uv));
            if (dir.y >= -1e-4f) continue;  // sky
            const float t_far = std::min(eye.y / -dir.y, ocean_far);
            const glm::vec3 floor = eye + dir * t_far;
            if (floor.y >= highest_wave) continue;  // above every crest as far as the march looks
            include(uv);
            if (const auto above = view_uv_of(view, eye, {floor.x, highest_wave, floor.z})) include(*above);
        }
    if (!any) return layout;
    low = glm::max(low - spacing, window.origin - window.extent);
    high = glm::min(high + spacing, window.origin + 2.0f * window.extent);
    layout.origin = low;
    layout.extent = high - low;
    const glm::vec2 texels =
        glm::ceil(layout.extent / window.extent * glm::vec2(target_size) * ocean_height_map_scale);
    layout.size = glm::clamp(glm::ivec2(texels), glm::ivec2(1), glm::ivec2(ocean_height_map_max_side));
    return layout;
}

float ocean_texel_angle(const render::ViewBasis& view, const OceanHeightMapLayout& layout) {
    if (layout.empty()) return 0;
    // A texel is extent / size of the view's uv, and the view's uv spans 2 scale at distance 1.
    const glm::vec2 angle = 2.0f * view.scale * layout.extent / glm::vec2(layout.size);
    return std::sqrt(angle.x * angle.y);
}

}  // namespace puddle::systems
