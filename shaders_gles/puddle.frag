#version 300 es
// The puddle image (REFERENCE.md section 1): a box of water whose top is displaced by the wave field, seen from
// the camera; Fresnel-Schlick between a rotated environment reflection and the ground refracted through
// murky water; then fog, vignette, tone mapping and sRGB encoding.
//
// Choices that are the same for every pixel are #defines, set by the render system from the parameters
// (src/render/puddle_variant.hpp), so no pixel pays for a branch it never takes: a GPU runs both sides of a
// branch its neighbours disagree on, and llvmpipe runs both sides of every branch.
//   METHOD_RAYMARCH: the reference's sphere-trace of the displaced box (render.march_steps reads);
//                    otherwise meet the flat top analytically and refine once (1 read).
//   SHORE:           puddle.shape = shore: the water's top is an endless plane of wet setts, water only
//                    inside an irregular shoreline (shallower toward it), the setts darker and glossier
//                    toward the water, everything fading into look.haze_color with distance.
//   GROUND_PAVING:   the procedural setts, drawn here; GROUND_IMAGE: the ground is u_ground (ground.image);
//                    neither: the checkerboard.
//   GROUND_HIDDEN:   turbidity is so high that no ground can show through: no refraction at all.
//   ENV_RGBM:        the cube holds RGBM texels (no half-float render targets).
//   TONEMAP:         the look.tonemap operator, a TONEMAP_* constant of colour.glsl.
//   CLOUD_LAYER:     the cube is the procedural sky without its clouds, its alpha how much cloud may cover
//                    each texel; the drifting layer (u_clouds) is laid over it (assets/cloud_layer.hpp).
// The displacement is tiny next to the box, so both methods find the same point (a test compares the pictures).
precision highp float;

#include "surface_encoding.glsl"
#include "colour.glsl"

in vec2 v_uv;  // 0..1 across the whole view, of which this target may be a tile (view_window.vert)
out vec4 o_color;

uniform sampler2D u_surface;   // height, hL - hR, hD - hU (surface.frag)
uniform samplerCube u_env;     // linear radiance: sRGB8 decoded by the sampler, half float, or RGBM
uniform sampler2D u_ground;    // sRGB: sampled as linear
uniform sampler2D u_clouds;    // CLOUD_LAYER: cloud coverage in R, one tile of the deck, repeating

// Camera and everything else uniform across the screen, computed once per frame on the CPU.
uniform vec3 u_camera_position;
uniform vec3 u_cam_forward;
uniform vec3 u_cam_right;
uniform vec3 u_cam_up;
uniform vec2 u_cam_scale;      // tan(fov / 2) * (aspect, 1), of the whole view (v_uv spans it)
uniform mat3 u_env_matrix;     // rotation about +Y by environment.rotation
uniform float u_env_scale;     // 2^environment.exposure
uniform vec2 u_cloud_offset;   // CLOUD_LAYER: how far the clouds have drifted (toward +x, +z), in tiles
uniform float u_cloud_scale;   // 1 / deck units a tile spans
uniform vec3 u_cloud_base;     // cloud undersides lit by the city (linear radiance)
uniform vec3 u_cloud_top;      // clouds overhead
uniform vec3 u_cloud_halo;     // silver added near the moon, per unit of cos(angle to it) above 0.96
uniform vec3 u_moon_direction;
uniform vec4 u_surface_map;    // surface uv = xz * map.xy + map.zw: the puddle once, or a capillary tile repeated
uniform vec2 u_slope_scale;    // world slope per unit of height difference (hR - hL, hU - hD) in world units:
                               // texels per world unit / 2
uniform float u_height_units;  // world units per unit of stored height
uniform float u_normal_scale;  // normal's tilt per unit of (hL - hR, hD - hU)

// Parameters, named after the registry (params.def).
uniform vec3 u_puddle_size;
uniform float u_puddle_depth;
uniform float u_water_reflectivity;
uniform float u_water_turbidity;
uniform vec3 u_water_tint;
uniform float u_ground_scale;
uniform float u_look_fog_density;
uniform float u_look_vignette;
uniform int u_render_march_steps;
uniform vec3 u_look_haze_color;
uniform vec4 u_shore;          // SHORE: the puddle's centre (x, z) and radii (x, z), world units
uniform vec3 u_under_filter;   // SHORE: 0.7 * (1 - 0.5 * water.tint), what the water passes of the ground
uniform float u_reflect_gain;      // SHORE: mix(0.3, 0.8, water.reflectivity) - 0.3, the reflection's Fresnel gain
uniform vec3 u_splash_light;       // SHORE: what a full splash adds, the night's glow (look.haze_color) brightened
uniform float u_top;               // the water's level: puddle.size.y / 2
uniform vec3 u_tint_glow;          // SHORE: the water's own faint light, 0.15 * water.tint
uniform float u_floor_drop;        // SHORE: how far the floor lies below the level at the deepest, 0.6 (top + depth)

const float IOR = 1.333;

// Height, its differences and (alpha) the splashes there.
vec4 surface_at(vec2 xz) {
    vec2 uv = xz * u_surface_map.xy + u_surface_map.zw;
    vec4 texel = texture(u_surface, uv);
    return vec4(decode_surface(texel.rgb), texel.a);
}

float top() { return u_top; }

// bias: mip levels coarser than the footprint asks for, a rough surface's blur (0: a mirror).
vec3 environment(vec3 dir, float bias) {
    vec3 e = u_env_matrix * dir;
    vec4 texel = texture(u_env, e, bias);
#ifdef ENV_RGBM
    return decode_rgbm(texel) * u_env_scale;
#else
    vec3 sky = texel.rgb;
#ifdef CLOUD_LAYER
    // Where the ray meets a flat deck one unit up (cloud_layer_uv), the layer drifted; lit from below
    // toward the horizon, darker overhead, silver within about 16 degrees of the moon.
    float up = max(e.y, 0.0);
    vec2 deck = e.xz * (u_cloud_scale / (up + 0.1)) - u_cloud_offset;  // the clouds move by +offset
    float cover = texture(u_clouds, deck, bias).r * texel.a;
    vec3 cloud = mix(u_cloud_base, u_cloud_top, up) + u_cloud_halo * max(dot(e, u_moon_direction) - 0.96, 0.0);
    sky = mix(sky, cloud, cover);
#endif
    return sky * u_env_scale;
#endif
}

#ifdef METHOD_RAYMARCH
// The finest level: inside the march's loop there are no derivatives to choose a level by (the pass
// binds the surface's marched_sampler, bilinear, for the same reason).
float water_height(vec2 xz) {
    vec2 uv = xz * u_surface_map.xy + u_surface_map.zw;
    return top() + decode_surface(textureLod(u_surface, uv, 0.0).rgb).r * u_height_units;
}

// Slab intersection with the axis-aligned box of half size h.
bool enter_box(vec3 o, vec3 d, vec3 h, out float t_near) {
    vec3 inv = 1.0 / d;
    vec3 t0 = (-h - o) * inv, t1 = (h - o) * inv;
    vec3 lo = min(t0, t1), hi = max(t0, t1);
    t_near = max(max(lo.x, lo.y), max(lo.z, 0.0));
    float t_far = min(min(hi.x, hi.y), hi.z);
    return t_near <= t_far;
}

// Distance to the box whose top face is displaced by the water height (a bound, as sphere tracing needs).
float water_sdf(vec3 p) {
    vec3 h = 0.5 * u_puddle_size;
    vec3 q = abs(p) - h;
    q.y = max(p.y - water_height(p.xz), -p.y - h.y);
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

bool hit_water(vec3 o, vec3 d, out vec3 p, out vec4 s) {
    float t;
    vec3 bound = 0.5 * u_puddle_size + vec3(0.0, 4.0 * u_height_units, 0.0);  // widened by the displacement
    if (!enter_box(o, d, bound, t)) return false;
    for (int i = 0; i < 64; ++i) {
        if (i >= u_render_march_steps) break;
        float dist = water_sdf(o + t * d);
        if (dist < 1e-3) break;
        t += dist;
    }
    p = o + t * d;
    s = surface_at(p.xz);
    return water_sdf(p) < 0.05;
}
#else
// Meet the flat top, read the surface there once, and step to where the plane through that texel's
// height, tilted by its slopes, meets the ray (one Newton step on the height; the displacement is a
// fraction of a unit, so one step lands on it). The same texel gives the normal.
bool hit_water(vec3 o, vec3 d, out vec3 p, out vec4 s) {
    float down = min(d.y, -1e-4);
    p = o + ((top() - o.y) / down) * d;
#ifdef SHORE
    bool inside = d.y < 0.0;  // the plane goes on; the shoreline decides what is water
#else
    bool inside = d.y < 0.0 && all(lessThanEqual(abs(p.xz), 0.5 * u_puddle_size.xz));
#endif
    // A ray that misses reads the surface at a harmless place: at p (where the plane's 1e-4 slope puts
    // it, 1e4 times further than the sky) its neighbours' texture footprint is unbounded, and llvmpipe's
    // anisotropic filter then takes minutes a frame.
    s = surface_at(inside ? p.xz : vec2(0.0));
    vec2 slope = -s.gb * u_slope_scale * u_height_units;  // d(height)/dx, d(height)/dz in world units
    float closing = min(down - dot(slope, d.xz), 0.5 * down);  // how fast the ray meets the tilted plane
    p += (s.r * u_height_units / closing) * d;
    return inside;
}
#endif

float hash12(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

#if defined(GROUND_IMAGE)
vec3 ground_colour(vec2 xz) { return texture(u_ground, xz * u_ground_scale).rgb * 0.6; }
#elif defined(GROUND_PAVING)
// Wet granite setts in running bond: 4 stones across and 6 rows along each ground.scale tile, every row
// shifted half a stone (and a little more, hashed), each stone its own shade, slightly domed, with dark
// joints. Drawn here, not read from a texture: on llvmpipe one filtered read cost a fifth of the frame,
// this costs about what the checkerboard does. The joints widen by the pixel's footprint (fwidth) and a
// stone smaller than a few pixels fades to the pattern's mean, so far rows do not shimmer.
vec3 ground_colour(vec2 xz) {
    vec2 q = xz * u_ground_scale * vec2(4.0, 6.0);  // in stones
    // Before the rows' shift: it jumps at every row joint, and a pixel there would seem to span half a
    // stone (the joint drawn as the pattern's mean: light dashes along every row).
    vec2 footprint = fwidth(q);
    float row = floor(q.y);
    q.x += 0.5 * row + 0.13 * fract(row * 0.618034);  // the golden ratio's sequence: no two rows alike
    vec2 stone_id = floor(q);
    vec2 edge = 0.5 - abs(fract(q) - 0.5);  // to the stone's nearest side, per axis: 0 at a joint
    vec2 joint = smoothstep(0.04 - footprint, 0.04 + footprint, edge);
    vec2 dome = 0.8 + 0.2 * smoothstep(0.0, 0.3, edge);
    float stone = joint.x * joint.y * dome.x * dome.y * (0.6 + 0.4 * hash12(stone_id));
    stone = mix(stone, 0.6, smoothstep(0.2, 0.5, max(footprint.x, footprint.y)));  // 0.6: the mean
    vec3 srgb = (vec3(40.0, 36.0, 32.0) + vec3(120.0, 110.0, 100.0) * stone) / 255.0;
    return srgb * srgb * 0.6;  // squared: near enough to sRGB's decoding for a made-up stone
}
#else
vec3 ground_colour(vec2 xz) {
    vec2 tile = floor(xz * u_ground_scale);
    float light = mod(tile.x + tile.y, 2.0);  // 0 or 1
    vec3 c = mix(vec3(0.15, 0.12, 0.10), vec3(0.25, 0.22, 0.20), light);
    return c + (hash12(floor(xz * 16.0)) - 0.5) * 0.05;  // +-0.025 grain
}
#endif

#ifdef SHORE
// Where the shoreline is, in units of the puddle's radius: below 0 in the water, 0 on the waterline. An
// ellipse bent by sines of incommensurate frequencies, so no stretch of shore repeats another.
float shore_distance(vec2 xz) {
    vec2 q = (xz - u_shore.xy) / u_shore.zw;
    float wobble = 0.11 * sin(2.3 * q.x + 1.4 * sin(1.9 * q.y) + 0.7) + 0.06 * sin(4.1 * q.y - 1.1 * q.x + 2.0);
    return length(q) - 1.0 + wobble;
}
#endif

// What the water shows of the ground at p: refracted, fading into the tint with the path through the water
// (Beer's law), then filtered by the water.
vec3 seen_ground(vec3 p, vec3 d, vec3 n) {
    vec3 filter_ = 0.7 * (1.0 - 0.5 * u_water_tint);
#ifdef GROUND_HIDDEN
    return u_water_tint * filter_;  // what the mix below gives once visibility is nil
#else
    vec3 t = refract(d, n, 1.0 / IOR);
    if (t.y >= 0.0) return 0.3 * u_water_tint;  // a ray bent upward never meets the ground
    float along = (-u_puddle_depth - p.y) / t.y;  // distance through the water
    vec3 ground = mix(u_water_tint, ground_colour(p.xz + along * t.xz), exp(-along * u_water_turbidity));
    return ground * filter_;
#endif
}

void main() {
    vec2 ndc = v_uv * 2.0 - 1.0;
    vec3 o = u_camera_position;
    vec3 d = normalize(u_cam_forward + ndc.x * u_cam_scale.x * u_cam_right + ndc.y * u_cam_scale.y * u_cam_up);

    // The sky is read once per pixel, along the reflected ray on the water (or wet ground) and the view
    // ray beyond: the surface's own light is added before, and fog scales both after.
    vec3 look = d;           // where the sky is read
    float sky_share = 1.0;   // how much of it shows
    float blur = 0.0;        // how rough the reflecting surface is (environment's bias)
    vec3 own = vec3(0.0);    // the surface's own light: ground and tint
    float fog_keep = 1.0;    // the sky beyond the puddle is at infinity, unfogged
    vec3 p;
    vec4 s;
    bool water = hit_water(o, d, p, s);
    // A pixel that misses still runs the water's code where the GPU masks instead of branching (llvmpipe
    // always; a GPU where neighbouring pixels disagree): give it a harmless point on the water, or its
    // ground read at an unbounded place costs a thousand times a normal one (measured on llvmpipe).
    if (!water) {
        p = vec3(0.0, top(), 0.0);
        s = vec4(0.0);
    }
#ifdef SHORE
    const float f0 = 0.020373;  // ((1 - IOR) / (1 + IOR))^2
    // The plane is water inside the shoreline and wet setts beyond it; one ground read either way:
    // refracted under the water, or where the ray meets the stones.
    bool plane = water;
    float shore = shore_distance(p.xz);
    water = plane && shore < 0.0;
    float dry = smoothstep(0.0, 0.3, shore);  // 0 at the waterline, 1 a little away from it
    vec3 n = water ? normalize(vec3(s.g * u_normal_scale, 1.0, s.b * u_normal_scale)) : vec3(0.0, 1.0, 0.0);
    float x = 1.0 - abs(dot(d, n));
    float x2 = x * x;
    float fresnel = f0 + (1.0 - f0) * (x2 * x2 * x);
    // Shallower toward the waterline, where the setts show through.
    float floor_y = top() - u_floor_drop * max(0.02, smoothstep(0.0, 0.3, -shore));
    vec3 t = refract(d, n, 1.0 / IOR);
    float along = water ? (floor_y - p.y) / min(t.y, -1e-4) : 0.0;  // distance through the water
    vec3 stones = ground_colour(p.xz + along * t.xz);
    if (water) {
        sky_share = fresnel * u_reflect_gain + 0.3;
        // Stones under water are darker, as wet ones are; then Beer's law and the water's filter.
        vec3 under = mix(u_water_tint, 0.6 * stones, exp(-along * u_water_turbidity)) * u_under_filter;
        own = under * (1.0 - sky_share) + u_tint_glow * (1.0 - fresnel);
    } else if (plane) {
        // Wet setts: darker as water fills their pores, and toward the waterline a film that mirrors the
        // lights, blurred as the stones are rough (the film smooths them near the water).
        sky_share = mix(0.75, 0.15, dry) * fresnel;
        blur = mix(2.0, 5.0, dry);
        own = stones * mix(0.22, 0.45, dry) * (1.0 - sky_share);
    }
    if (plane) look = reflect(d, n);
    // A splash's droplets catch the night's glow from every side: they add it, brightened (on the wet
    // setts too, where the rain falls as well).
    own += s.a * u_splash_light;
    vec3 colour = own + sky_share * environment(look, blur);
    // The distance dissolves into the night's haze rather than ending at an edge.
    if (plane) colour = mix(u_look_haze_color, colour, exp(-distance(o, p) * u_look_fog_density));
#else
    const float f0 = ((1.0 - IOR) / (1.0 + IOR)) * ((1.0 - IOR) / (1.0 + IOR));
    if (water) {
        vec3 n = normalize(vec3(s.g * u_normal_scale, 1.0, s.b * u_normal_scale));

        float x = 1.0 - abs(dot(d, n));
        float x2 = x * x;
        float fresnel = f0 + (1.0 - f0) * (x2 * x2 * x);  // Schlick's (1 - cos)^5 without pow

        // mix(ground, reflection, w), with w = F * (m - 0.3) + 0.3 and m = mix(0.3, 0.8, reflectivity)
        float m = mix(0.3, 0.8, u_water_reflectivity);
        sky_share = fresnel * (m - 0.3) + 0.3;
        look = reflect(d, n);
        own = seen_ground(p, d, n) * (1.0 - sky_share) + 0.15 * u_water_tint * (1.0 - fresnel);
        fog_keep = mix(0.7, 1.0, exp(-distance(o, p) * u_look_fog_density));
    }
    vec3 colour = (own + sky_share * environment(look, blur)) * fog_keep;
#endif

    colour *= 1.0 - u_look_vignette * length(v_uv - 0.5);
    o_color = vec4(encode_srgb(tonemap(colour, TONEMAP)), 1.0);
}
