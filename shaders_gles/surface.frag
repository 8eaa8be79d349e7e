#version 300 es
// Folds what the render pass needs from the height field into one filterable texel per field texel:
// height and its central differences one texel apart (hL - hR, hD - hU). Filtering these linearly equals
// differencing linearly filtered heights, so the render pass takes one fetch where it would take five.
// PERIODIC: the field repeats (a capillary field), so the differences wrap around its edges, and rain
// falls on it: alpha holds the splashes of the drops that hit in the last SPLASH_SECONDS (0 elsewhere).
precision highp float;
precision highp int;

#include "surface_encoding.glsl"
#ifdef PERIODIC
#include "rain_cells.glsl"

uniform float u_texel_mm;     // the field's texel, mm
uniform float u_splash_gain;  // 0 to 1: rain.intensity's share of its default; 0 with no rain

// A splash: the crown and droplets a drop throws up, a few drop diameters across, gone in tens of
// milliseconds (LOOK.md). Drawn as a soft spot that widens from one to three diameters and fades as the
// droplets fall back; the render pass lights it with the scene. The drops are the last wave pass's
// (rain_cells.frag), SPLASH_SECONDS long.
const float SPLASH_SECONDS = 0.06;
float splash(vec2 p) {
    ivec2 c0 = rain_cells_near(p);
    float sum = 0.0;
    for (int j = 0; j < 8; ++j) {
        vec2 spot;
        vec4 drop = rain_cell(c0 + ivec2(j & 1, (j >> 1) & 1), j >> 2, 1, spot);  // age, diameter
        float life = drop.z / SPLASH_SECONDS;
        float reach = 0.5 * drop.w * (1.0 + 2.0 * life) / u_texel_mm;  // texels
        float r = distance(p, spot);
        float lit = (1.0 - life) * (1.0 - life) * (1.0 - smoothstep(0.5 * reach, reach + 0.7, r));
        sum += drop.z >= 0.0 ? lit : 0.0;
    }
    return min(sum, 1.0) * u_splash_gain;
}
#endif

#ifdef FIXED_POINT_SCALE
uniform highp isampler2D u_field;
float height(ivec2 p) { return float(texelFetch(u_field, p, 0).r) / FIXED_POINT_SCALE; }
#define AT(uv, dx, dy) (float(textureLodOffset(u_field, uv, 0.0, ivec2(dx, dy)).r) / FIXED_POINT_SCALE)
#else
uniform highp sampler2D u_field;
float height(ivec2 p) { return texelFetch(u_field, p, 0).r; }
#define AT(uv, dx, dy) textureLodOffset(u_field, uv, 0.0, ivec2(dx, dy)).r
#endif

out vec4 o_surface;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#ifdef PERIODIC
    // The neighbours through the field's repeating nearest sampler (as wave_step.frag reads them): an
    // integer % per read costs much more on llvmpipe, which has no vector division.
    vec2 uv = gl_FragCoord.xy / vec2(textureSize(u_field, 0));
    float hL = AT(uv, -1, 0);
    float hR = AT(uv, 1, 0);
    float hD = AT(uv, 0, -1);
    float hU = AT(uv, 0, 1);
#else
    ivec2 hi = textureSize(u_field, 0) - 1;
    float hL = height(clamp(p - ivec2(1, 0), ivec2(0), hi));
    float hR = height(clamp(p + ivec2(1, 0), ivec2(0), hi));
    float hD = height(clamp(p - ivec2(0, 1), ivec2(0), hi));
    float hU = height(clamp(p + ivec2(0, 1), ivec2(0), hi));
#endif
#ifdef PERIODIC
    float splashes = u_splash_gain > 0.0 ? splash(gl_FragCoord.xy) : 0.0;
#else
    float splashes = 0.0;
#endif
    o_surface = vec4(encode_surface(vec3(height(p), hL - hR, hD - hU)), splashes);
}
