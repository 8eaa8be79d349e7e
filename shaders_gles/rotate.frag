#version 300 es
// Turns the finished picture onto the screen by quarter turns, clockwise as seen on the screen, for
// portrait or upside-down mounting (the Raspberry Pi's display controller cannot turn a plane by 90).
// The canvas holds the picture upright; each screen pixel fetches exactly one canvas texel.
precision highp float;
precision highp int;

uniform highp sampler2D u_canvas;
uniform int u_quarter_turns;  // 1, 2 or 3
out vec4 o_color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);  // screen pixel, origin bottom left
    ivec2 last = textureSize(u_canvas, 0) - 1;
    ivec2 src;
    if (u_quarter_turns == 1) src = ivec2(last.x - p.y, p.x);
    else if (u_quarter_turns == 2) src = ivec2(last.x - p.x, last.y - p.y);
    else src = ivec2(p.y, last.y - p.x);
    o_color = texelFetch(u_canvas, src, 0);
}
