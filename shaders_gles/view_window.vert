#version 300 es
// The scene passes' triangle (fullscreen.vert's), with v_uv across the whole view rather than the target:
// the target shows the window u_view_window of the view (render/view_window.hpp), all of it on a single
// screen, a tile of it on a screen of a video wall. Shaders that work in screen space from v_uv then see
// the wall's coordinates, and the tiles join into one picture.
uniform vec4 u_view_window;  // the target's bottom-left corner (xy) and size (zw), as fractions of the view
out vec2 v_uv;               // 0..1 across the whole view, (0,0) at its bottom left

void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    v_uv = u_view_window.xy + p * u_view_window.zw;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
