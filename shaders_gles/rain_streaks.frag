#version 300 es
// A rain streak (rain_streaks.vert places its quad), blended as light (Blend::Lit: the target times
// 1 + this output): a streak lights up by what lies behind it, bright in front of lit windows and their
// reflections, all but invisible against the dark, as rain at night is seen.
precision highp float;
precision highp int;

#include "hash.glsl"
#include "rain_streak_cells.glsl"

in vec2 v_uv;
flat in ivec2 v_cell;
flat in int v_layer;
out vec4 o_color;

uniform vec4 u_layer_fall;
uniform vec3 u_overlay_rain_color;
uniform float u_overlay_rain_opacity;

void main() {
    vec2 local = v_uv * streak_cells(v_layer) - vec2(v_cell);
    float offset = streak_offset(v_layer, v_cell);
    float half_width = streak_half_width(v_layer);
    float across = 1.0 - smoothstep(0.5 * half_width, half_width, abs(local.x - (0.2 + 0.6 * offset)));
    float fall = fract(local.y + u_layer_fall[v_layer] + offset);
    float along = smoothstep(0.0, 0.04, fall) * smoothstep(STREAK_LENGTH, 0.0, fall);
    // At full opacity the nearest streak (weight 0.9) doubles what is behind it, tinted by overlay.rain_color.
    o_color = vec4(u_overlay_rain_color * (across * along * LAYERS[v_layer].z * u_overlay_rain_opacity / 0.9 * 1.25), 1.0);
}
