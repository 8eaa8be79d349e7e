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
#include "hash.glsl"
#include "rain_impacts.glsl"

uniform float u_texel_mm;     // the field's texel, mm
uniform float u_splash_gain;  // 0 to 1: rain.intensity's share of its default

// A splash: the crown and droplets a drop throws up, a few drop diameters across, gone in tens of
// milliseconds (LOOK.md). Drawn as a soft spot that widens from one to three diameters and fades as the
// droplets fall back; the render pass lights it with the scene.
const float SPLASH_SECONDS = 0.06;
float splash(vec2 p) {
    ivec2 c0 = rain_cells_near(p);
    float sum = 0.0;
    for (int j = 0; j < 4; ++j) {
        for (int k = 0; k < 2; ++k) {
            vec2 spot;
            float age, diameter;
            if (!rain_impact(c0 + ivec2(j & 1, j >> 1), k, SPLASH_SECONDS, spot, age, diameter)) continue;
            float life = age / SPLASH_SECONDS;
            float reach = 0.5 * diameter * (1.0 + 2.0 * life) / u_texel_mm;  // texels
            float r = distance(p, spot);
            sum += (1.0 - life) * (1.0 - life) * (1.0 - smoothstep(0.5 * reach, reach + 0.7, r));
        }
    }
    return min(sum, 1.0) * u_splash_gain;
}
#endif

#ifdef FIXED_POINT_SCALE
uniform highp isampler2D u_field;
float height(ivec2 p) { return float(texelFetch(u_field, p, 0).r) / FIXED_POINT_SCALE; }
#else
uniform highp sampler2D u_field;
float height(ivec2 p) { return texelFetch(u_field, p, 0).r; }
#endif

out vec4 o_surface;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#ifdef PERIODIC
    ivec2 n = textureSize(u_field, 0);
    float hL = height((p - ivec2(1, 0) + n) % n);
    float hR = height((p + ivec2(1, 0)) % n);
    float hD = height((p - ivec2(0, 1) + n) % n);
    float hU = height((p + ivec2(0, 1)) % n);
#else
    ivec2 hi = textureSize(u_field, 0) - 1;
    float hL = height(clamp(p - ivec2(1, 0), ivec2(0), hi));
    float hR = height(clamp(p + ivec2(1, 0), ivec2(0), hi));
    float hD = height(clamp(p - ivec2(0, 1), ivec2(0), hi));
    float hU = height(clamp(p + ivec2(0, 1), ivec2(0), hi));
#endif
#ifdef PERIODIC
    float splashes = u_rain.z > 0.0 && u_splash_gain > 0.0 ? splash(gl_FragCoord.xy) : 0.0;
#else
    float splashes = 0.0;
#endif
    o_surface = vec4(encode_surface(vec3(height(p), hL - hR, hD - hU)), splashes);
}
