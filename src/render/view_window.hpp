#pragma once
// The view is one virtual screen; a frame target shows a window of it. A single screen shows all of it.
// A screen of a video wall (wall.*, docs/video-walls.md) shows its tile: the whole view has the size of
// the wall, columns * width + (columns - 1) * bezel_x by rows * height + (rows - 1) * bezel_y pixels, and
// the screens' pictures sit in it with the bezels' gaps between them, so the picture goes on behind the
// frames. Everything the scene passes work out in screen space takes the whole view's coordinates: the
// ray through a pixel (an off-axis sub-frustum of the wall's camera: pixel (x, y) of a tile sees what
// pixel (x, y) + offset of the whole view sees), the aspect, vignette, the street's horizon and the rain's
// streaks. view_window.vert hands the fragment shaders v_uv across the whole view from u_view_window.

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "params/param_store.hpp"

namespace puddle::render {

struct ViewWindow {
    glm::vec2 origin{0, 0};  // the target's bottom-left corner in the whole view, as fractions of it (y up)
    glm::vec2 extent{1, 1};  // the target's width and height as fractions of the whole view's

    // u_view_window: (origin, extent).
    glm::vec4 uniform() const { return {origin, extent}; }
    // The whole view in pixels of a target of `target_size` pixels that shows this window.
    glm::vec2 view_size(glm::ivec2 target_size) const { return glm::vec2(target_size) / extent; }
    // The whole view's width / height: what sets the wall camera's horizontal field of view.
    float view_aspect(glm::ivec2 target_size) const;

    bool operator==(const ViewWindow&) const = default;
};

// This screen's window of the wall that wall.* describes, for an upright picture (after display.rotation
// and wall.rotation) of `screen` pixels; the bezels are in the same pixels. The whole view in mirror mode
// and without a wall (1 x 1). A column or row past the wall (a knob's or the broker's value; start-up and
// config reloads refuse them, params/wall_check.hpp) is clamped to the last one.
ViewWindow wall_window(const params::Params& params, glm::vec2 screen);

}  // namespace puddle::render
