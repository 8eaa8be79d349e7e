#version 300 es
// One quad per cell of every streak layer, from gl_InstanceID (no vertex buffer), drawn over the cell's
// streak when the cell holds one and empty when not, so the pass shades only the few pixels the rain
// covers instead of the whole view. A streak's fall repeats every cell: where it runs off the cell's
// bottom it comes back at its top, so each cell has two instances, the streak and its wrapped part.
precision highp float;
precision highp int;

#include "hash.glsl"
#include "rain_streak_cells.glsl"

uniform vec4 u_view_window;  // the target's bottom-left corner (xy) and size (zw), as fractions of the view
uniform vec4 u_layer_fall;   // per layer, far to near: how far its streaks have fallen, in cells modulo 1

out vec2 v_uv;               // 0..1 across the whole view, as view_window.vert's
flat out ivec2 v_cell;       // the streak's cell in its layer
flat out int v_layer;

void main() {
    int cell_index = gl_InstanceID / 2;
    int layer = 0;
    for (; layer < STREAK_LAYERS - 1; ++layer) {
        ivec2 n = streak_cell_counts(layer);
        if (cell_index < n.x * n.y) break;
        cell_index -= n.x * n.y;
    }
    vec2 cells = streak_cells(layer);
    ivec2 counts = streak_cell_counts(layer);
    ivec2 cell = ivec2(cell_index % counts.x, cell_index / counts.x);
    v_cell = cell;
    v_layer = layer;
    gl_Position = vec4(2.0, 2.0, 0.0, 1.0);  // outside the view: an empty quad
    v_uv = vec2(0.0);
    if (cell.y >= counts.y || !streak_present(layer, cell)) return;

    // Lit where fract(y + fall + offset) is in 0..STREAK_LENGTH for y in 0..1 across the cell: from
    // 1 - s (this instance's copy 0) or from -s (copy 1, the part that wrapped), s = fract(fall + offset).
    float offset = streak_offset(layer, cell);
    float s = fract(u_layer_fall[layer] + offset);
    float y0 = (gl_InstanceID % 2 == 0 ? 1.0 : 0.0) - s;
    vec2 lo = vec2(0.2 + 0.6 * offset - streak_half_width(layer), y0);
    vec2 hi = vec2(lo.x + 2.0 * streak_half_width(layer), y0 + STREAK_LENGTH);
    lo = max(lo, vec2(0.0));
    hi = min(hi, vec2(1.0));
    if (hi.x <= lo.x || hi.y <= lo.y) return;

    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));  // a triangle strip's 4 corners
    v_uv = (vec2(cell) + mix(lo, hi, corner)) / cells;
    gl_Position = vec4((v_uv - u_view_window.xy) / u_view_window.zw * 2.0 - 1.0, 0.0, 1.0);
}
