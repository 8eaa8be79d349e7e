#include "render/view_window.hpp"

#include <algorithm>
#include <glm/common.hpp>

namespace puddle::render {

using params::ParamId;

float ViewWindow::view_aspect(glm::ivec2 target_size) const {
    const glm::vec2 view = view_size(glm::max(target_size, glm::ivec2(1)));
    return view.x / view.y;
}

ViewWindow wall_window(const params::Params& params, glm::vec2 screen) {
    const glm::ivec2 grid(params.get<ParamId::wall_columns>(), params.get<ParamId::wall_rows>());
    if (params.get<ParamId::wall_mode>() == params::WallMode::mirror || grid == glm::ivec2(1)) return {};
    const int column = std::clamp(params.get<ParamId::wall_column>(), 0, grid.x - 1);
    const int row = std::clamp(params.get<ParamId::wall_row>(), 0, grid.y - 1);
    const glm::vec2 bezel(params.get<ParamId::wall_bezel_x>(), params.get<ParamId::wall_bezel_y>());
    screen = glm::max(screen, glm::vec2(1));
    const glm::vec2 whole = glm::vec2(grid) * screen + glm::vec2(grid - 1) * bezel;
    // Rows count from the top, as people number them; the view's y goes up, as GL's.
    const glm::vec2 corner = glm::vec2(column, grid.y - 1 - row) * (screen + bezel);
    return {corner / whole, screen / whole};
}

}  // namespace puddle::render
