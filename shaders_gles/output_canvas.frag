#version 300 es
// The last pass when the scene could not render straight to the screen: turns the finished picture by
// quarter turns, clockwise as seen on the screen, for portrait or upside-down mounting (the Raspberry
// Pi's display controller cannot turn a plane by 90), and with SCALED also scales it up from a smaller
// canvas (render.scale). Unscaled, each screen pixel fetches exactly one canvas texel; scaled, the
// canvas is filtered bilinearly. Both multiply by u_brightness (display.brightness; 1 leaves the picture
// as it is), the one multiply of the output's dimming.
precision highp float;
precision highp int;

uniform highp sampler2D u_canvas;
uniform int u_quarter_turns;  // 0 (no turn: scaled or dimmed only), 1, 2 or 3
uniform float u_brightness;   // 0 to 1
out vec4 o_color;

#ifdef SCALED
uniform vec2 u_screen_size;

void main() {
    vec2 q = gl_FragCoord.xy / u_screen_size;  // the pixel's centre as a fraction of the screen
    vec2 uv = q;
    if (u_quarter_turns == 1) uv = vec2(1.0 - q.y, q.x);
    else if (u_quarter_turns == 2) uv = 1.0 - q;
    else if (u_quarter_turns == 3) uv = vec2(q.y, 1.0 - q.x);
    o_color = texture(u_canvas, uv);
    o_color.rgb *= u_brightness;
}
#else
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);  // screen pixel, origin bottom left
    ivec2 last = textureSize(u_canvas, 0) - 1;
    ivec2 src = p;
    if (u_quarter_turns == 1) src = ivec2(last.x - p.y, p.x);
    else if (u_quarter_turns == 2) src = ivec2(last.x - p.x, last.y - p.y);
    else if (u_quarter_turns == 3) src = ivec2(p.y, last.y - p.x);
    o_color = texelFetch(u_canvas, src, 0);
    o_color.rgb *= u_brightness;
}
#endif
