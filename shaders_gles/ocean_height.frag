#version 300 es
// The ocean's height map (ocean.method = height_map; systems/ocean/ocean_height_map.hpp): each texel holds
// the height of the sea at the point of the plane y = u_map_plane that the eye sees through it, of every
// octave the texel resolves (sea_height_filtered), and the slope variance of those it cannot. The map's texels are view directions (view_window.vert hands them as v_uv over the map's window of
// the view), so it is fine near the eye and coarse far away, as the screen is; ocean.frag reads it along
// each ray where the other methods compute the waves.
precision highp float;
precision highp int;

#include "hash.glsl"
#include "ocean_waves.glsl"

in vec2 v_uv;  // the view direction of this texel: 0..1 across the whole view, beyond it at the margins
out vec4 o_height;

uniform vec3 u_cam_forward;
uniform vec3 u_cam_right;
uniform vec3 u_cam_up;
uniform vec2 u_cam_scale;
uniform vec3 u_ocean_camera_position;
uniform float u_map_plane;
uniform float u_texel_angle;  // radians a map texel spans (about two pixels' worth)

void main() {
    vec2 ndc = v_uv * 2.0 - 1.0;
    vec3 dir = u_cam_forward + ndc.x * u_cam_scale.x * u_cam_right + ndc.y * u_cam_scale.y * u_cam_up;
    if (dir.y > -1e-5) {  // above the horizon: no ray that meets the sea reads it
        o_height = vec4(0.0);
        return;
    }
    vec3 unit = normalize(dir);
    float distance = (u_ocean_camera_position.y - u_map_plane) / -unit.y;
    vec2 p = u_ocean_camera_position.xz + unit.xz * distance;
    // The ground a texel covers: distance times its angle across, and that over the sine of the grazing
    // angle along the view; the octaves fade by the longer, so that none is sampled too sparsely along
    // the rays that read it (a grazing ray crosses many texels' depth).
    float footprint = distance * u_texel_angle / -unit.y;
    float lost_variance;
    float h = sea_height_filtered(p, u_ocean_octaves, footprint, lost_variance);
    o_height = vec4(h, lost_variance, 0.0, 1.0);
}
