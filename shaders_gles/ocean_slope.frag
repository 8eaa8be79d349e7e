#version 300 es
// The ocean's height map, second pass (systems/ocean/ocean_height_map.hpp): each texel gets, beside the
// height ocean_height.frag laid there, the sea's slope (dh/dx, dh/dz) from its neighbours' heights
// over the points of the plane they show: the differences to the next texel across and up, solved for the
// gradient, which is the slope half a texel up and right of the texel's centre (ocean.frag reads it there),
// so ocean.frag reads the normal at a hit in one texel. The slope is the map's: over a texel, two pixels.
precision highp float;
precision highp int;

in vec2 v_uv;  // the view direction of this texel, as in ocean_height.frag
out vec4 o_map;

uniform highp sampler2D u_heights;  // ocean_height.frag's output
uniform vec4 u_map_window;          // as ocean.frag's: the map's corner and size in the view's uv
uniform vec3 u_cam_forward;
uniform vec3 u_cam_right;
uniform vec3 u_cam_up;
uniform vec2 u_cam_scale;
uniform vec3 u_ocean_camera_position;
uniform float u_map_plane;

// The point (x, z) of the map's plane seen in view direction uv.
vec2 plane_point(vec2 uv) {
    vec2 ndc = uv * 2.0 - 1.0;
    vec3 dir = u_cam_forward + ndc.x * u_cam_scale.x * u_cam_right + ndc.y * u_cam_scale.y * u_cam_up;
    return u_ocean_camera_position.xz + dir.xz * ((u_ocean_camera_position.y - u_map_plane) / -min(dir.y, -1e-5));
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(u_heights, 0) - 1;
    ivec2 right = ivec2(min(texel.x + 1, last.x), texel.y), above = ivec2(texel.x, min(texel.y + 1, last.y));
    vec2 step_uv = u_map_window.zw / vec2(textureSize(u_heights, 0));
    vec2 here = plane_point(v_uv);
    vec2 a = plane_point(v_uv + vec2(step_uv.x, 0.0)) - here;
    vec2 b = plane_point(v_uv + vec2(0.0, step_uv.y)) - here;
    vec2 h_and_variance = texelFetch(u_heights, texel, 0).rg;
    float h = h_and_variance.r;
    float ha = texelFetch(u_heights, right, 0).r - h;
    float hb = texelFetch(u_heights, above, 0).r - h;
    float det = a.x * b.y - a.y * b.x;
    vec2 slope = abs(det) > 1e-12 ? vec2(ha * b.y - hb * a.y, a.x * hb - b.x * ha) / det : vec2(0.0);
    o_map = vec4(h, slope, h_and_variance.g);
}
