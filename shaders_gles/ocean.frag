#version 300 es
// Open water (REFERENCE.md section 2): the view ray finds the choppy fBm height field (ocean_waves.glsl);
// the hit is lit by a low sun, a warm back light and the sky, with a Fresnel reflection of the sky and its
// sun, and the body brighter through the crests. Three ways to find the sea (ocean.method):
//   OCEAN_HEIGHT_MAP ("height_map", the default): the height of every octave was laid this frame into a
//                map on the plane of the highest crest, seen from the eye (ocean_height.frag,
//                systems/ocean/ocean_height_map.hpp), so the march reads a texel where the others
//                compute the waves: coarse steps to the first point under the water, then secant steps,
//                and the normal from the map's neighbouring texels (a normal filtered to the map's
//                footprint, about two pixels, so far crests do not sparkle).
//   OCEAN_SECANT ("secant"): the same search, computing four octaves at each step and every octave three
//                times for the normal (after the height-map tracing of Alexander Alekseev's "Seascape",
//                Shadertoy 2014); the ocean's method where the map cannot be made.
//   otherwise ("reference"): the reference's march of up to 200 steps on the full height.
precision highp float;
precision highp int;

#include "hash.glsl"
#include "ocean_waves.glsl"

in vec2 v_uv;  // 0..1 across the whole view, of which this target may be a tile (view_window.vert)
out vec4 o_color;

uniform vec3 u_cam_forward;
uniform vec3 u_cam_right;
uniform vec3 u_cam_up;
uniform vec2 u_cam_scale;      // tan(fov / 2) * (aspect, 1), of the whole view (v_uv spans it)

uniform vec3 u_ocean_camera_position;
uniform vec3 u_ocean_sea_color;

const int MARCH_STEPS = 200;
const float MARCH_EPSILON = 1e-4;
const float NORMAL_EPSILON = 1e-3;
const float FAR = 400.0;
// A sun low over the sea ahead and to the right, so its glitter runs toward the viewer.
const vec3 SUN = normalize(vec3(0.35, 0.23, -1.0));
const vec3 SUN_COLOR = vec3(1.0, 0.78, 0.52);
const vec3 BACK_LIGHT = vec3(0.52, 0.42, 0.34);
// The colour light takes through a crest thin enough to see into (green-blue, as shallow seawater).
const vec3 CREST_COLOR = vec3(0.16, 0.30, 0.26);

// A clear sky over the sea: haze at the horizon, deep blue overhead, and the sun with its glow. Rays below
// the horizon (a reflection off a steep wave's face) see the haze.
vec3 sky(vec3 dir) {
    float up = max(dir.y, 0.0);
    vec3 c = mix(vec3(0.70, 0.76, 0.82), vec3(0.10, 0.26, 0.56), pow(up, 0.5));
    float s = max(dot(dir, SUN), 1e-6), l = log2(s);
    c += SUN_COLOR * (0.16 * exp2(6.0 * l) + 0.3 * exp2(64.0 * l) + 1.5 * exp2(1200.0 * l));
    c += SUN_COLOR * 8.0 * smoothstep(0.99955, 0.9998, s);  // the disc
    return c;
}

#if defined(OCEAN_HEIGHT_MAP)
uniform sampler2D u_height_map;  // per texel: the height, dh/dx, dh/dz (ocean_slope.frag)
uniform vec4 u_map_window;  // the map's bottom-left corner and size in the view's uv (may reach past it)
uniform float u_map_plane;  // the plane the map lies on (units): the highest crest

// Along a view ray, where the map holds the sea under the ray's point at t: the point of the map's plane
// above it, seen from the eye, which is a projective function of t, (p0 + p1 t) / (z0 + z1 t) + offset,
// set up once a ray (a step is then three multiply-adds, a division and a texel read).
struct MapRay {
    vec2 p0, p1, offset;
    float z0, z1;
};

MapRay map_ray(vec3 dir) {
    float drop = u_map_plane - u_ocean_camera_position.y;
    vec2 k = 0.5 / (u_cam_scale * u_map_window.zw);
    MapRay r;
    r.p0 = drop * vec2(u_cam_right.y, u_cam_up.y) * k;
    r.p1 = vec2(dot(dir.xz, u_cam_right.xz), dot(dir.xz, u_cam_up.xz)) * k;
    r.z0 = drop * u_cam_forward.y;
    r.z1 = dot(dir.xz, u_cam_forward.xz);
    r.offset = (0.5 - u_map_window.xy) / u_map_window.zw;
    return r;
}

vec2 map_coord(MapRay r, float t) { return (r.p0 + r.p1 * t) / (r.z0 + r.z1 * t) + r.offset; }

MapRay marched;  // the ray march() follows (begin_ray)
void begin_ray(vec3 dir) { marched = map_ray(dir); }
float height_on_ray(vec3 p, float t) { return texture(u_height_map, map_coord(marched, t)).r; }

// The map's normal, tilted toward the eye by the slopes it could not hold: of a sea rougher than its
// mean surface, the eye sees more of the facets that face it (a mean visible normal; a steep facet
// reflects the sky higher up, and less of it), so far water does not turn into a mirror of the haze.
vec3 normal_at(vec3 p, vec3 dir, float t) {
    MapRay ray = map_ray(dir);
    // ocean_slope.frag's slope of a texel is half a texel up and right of its centre.
    vec3 texel = texture(u_height_map, map_coord(ray, t) - 0.5 / vec2(textureSize(u_height_map, 0))).gba;
    vec3 n = normalize(vec3(-texel.x, 1.0, -texel.y));
    vec2 toward_eye = -normalize(dir.xz);
    return normalize(n + vec3(toward_eye.x, 0.0, toward_eye.y) * sqrt(texel.z));
}
#else
void begin_ray(vec3 dir) {}
#ifdef OCEAN_SECANT
float height_on_ray(vec3 p, float t) { return sea_height(p.xz, min(4, u_ocean_octaves)); }  // the geometry's octaves
#else
float height_on_ray(vec3 p, float t) { return sea_height(p.xz, u_ocean_octaves); }
#endif

vec3 normal_at(vec3 p, vec3 dir, float t) {
    float h = sea_height(p.xz, u_ocean_octaves);
    float hx = sea_height(p.xz + vec2(NORMAL_EPSILON, 0.0), u_ocean_octaves);
    float hz = sea_height(p.xz + vec2(0.0, NORMAL_EPSILON), u_ocean_octaves);
    return normalize(vec3(h - hx, NORMAL_EPSILON, h - hz));
}
#endif

#if defined(OCEAN_HEIGHT_MAP) || defined(OCEAN_SECANT)
#ifdef OCEAN_HEIGHT_MAP
const int COARSE_STEPS = 8;  // a step is a texel read
const int SECANT_STEPS = 4;
#else
const int COARSE_STEPS = 6;
const int SECANT_STEPS = 5;
#endif

// The gap between the ray at t and the sea under it (positive above the water).
float gap_at(vec3 origin, vec3 dir, float t) {
    vec3 p = origin + dir * t;
    return p.y - height_on_ray(p, t);
}

// The distance along the ray to the sea, or -1 for a ray that meets none within FAR: the ray is bracketed
// between the plane of the highest crest and the sea's floor (no wave is lower than 0); COARSE_STEPS
// steps, closer together near the eye, find the first one under the water (so a grazing ray mostly meets
// the nearer crest; a crest thinner than a step can still be passed), then secant steps refine it between
// that step and the one before. An eye under a crest's height meets the water where it starts.
float march(vec3 origin, vec3 dir) {
    if (dir.y >= -1e-4) return -1.0;
    float t_near = max((origin.y - highest_wave()) / -dir.y, 0.0), t_far = min(origin.y / -dir.y, FAR);
    if (t_near >= t_far) return -1.0;
    begin_ray(dir);
    float t0 = t_near, g0 = gap_at(origin, dir, t_near);
    if (g0 < 0.0) return t_near;  // the eye is below the highest crest, and under this one
    float t1 = -1.0, g1 = 0.0;
    for (int i = 1; i <= COARSE_STEPS; ++i) {
        float f = float(i) / float(COARSE_STEPS);
        float t = mix(t_near, t_far, f * f);
        float g = gap_at(origin, dir, t);
        if (g < 0.0) {
            t1 = t;
            g1 = g;
            break;
        }
        t0 = t;
        g0 = g;
    }
    if (t1 < 0.0) return -1.0;  // still above the water at FAR
    float t = t0;
    for (int i = 0; i < SECANT_STEPS; ++i) {
        t = mix(t0, t1, g0 / max(g0 - g1, 1e-6));
        float g = gap_at(origin, dir, t);
        if (g < 0.0) {
            t1 = t;
            g1 = g;
        } else {
            t0 = t;
            g0 = g;
        }
    }
    return t;
}
#else
// Marches p.y - height(p.xz) along the ray; returns the distance, or -1 for a ray that meets no water.
float march(vec3 origin, vec3 dir) {
    float t = 0.0;
    for (int i = 0; i < MARCH_STEPS; ++i) {
        vec3 p = origin + dir * t;
        float gap = p.y - height_on_ray(p, t);
        if (gap < MARCH_EPSILON) return t;
        t += clamp(gap, 0.01, 2.0);
        if (t > FAR) break;
    }
    return -1.0;
}
#endif

vec3 sea_color(vec3 p, vec3 n, vec3 view) {
    float diffuse = max(dot(n, SUN), 0.0);
    float back = max(dot(n, normalize(vec3(-SUN.x, 0.0, -SUN.z))), 0.0);
    float dome = (0.2 + 0.8 * n.y) * 0.1;
    vec3 body = u_ocean_sea_color * (diffuse + dome) + u_ocean_sea_color * BACK_LIGHT * back;
    // Light through a crest: the higher the water stands, the thinner it is to the light behind it.
    body += CREST_COLOR * smoothstep(0.45, 1.0, p.y / max(highest_wave(), 1e-3)) * (0.4 + 0.6 * back);
    // Fresnel-Schlick, IOR 1.333 as in section 1.
    float f0 = 0.02;
    float fresnel = f0 + (1.0 - f0) * pow(1.0 - abs(dot(n, -view)), 5.0);
    return mix(body, sky(reflect(view, n)), fresnel);
}

void main() {
    vec2 ndc = v_uv * 2.0 - 1.0;
    vec3 dir = normalize(u_cam_forward + ndc.x * u_cam_scale.x * u_cam_right + ndc.y * u_cam_scale.y * u_cam_up);
    vec3 origin = u_ocean_camera_position;
    float t = dir.y < 0.0 ? march(origin, dir) : -1.0;
    vec3 color;
    if (t > 0.0) {
        vec3 p = origin + dir * t;
        color = sea_color(p, normal_at(p, dir, t), dir);
        // Far water fades into the haze: crests smaller than a pixel would only shimmer.
        float haze = smoothstep(0.3 * FAR, FAR, t);
        if (haze > 0.0) color = mix(color, sky(dir), haze);
    } else {
        color = sky(dir);
    }
    o_color = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
