#version 300 es
// The benchmark's floor: a fullscreen pass that samples one texture and writes it.
precision mediump float;
in vec2 v_uv;
out vec4 o_color;
uniform sampler2D u_source;
void main() { o_color = texture(u_source, v_uv); }
