#version 300 es
// One triangle that covers the target, made from gl_VertexID: no vertex buffer needed.
out vec2 v_uv;  // 0..1 across the target, (0,0) at the bottom left

void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    v_uv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
