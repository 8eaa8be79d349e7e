// Colour handling shared by the passes. Radiance is linear throughout; it is encoded to sRGB once, at
// the end of the puddle pass.
//
// RGBM: 8-bit storage of HDR radiance for GPUs without half-float render targets: colour = rgb * m *
// RGBM_RANGE, m in alpha, the smallest 8-bit m that holds the brightest channel. A linear scale (not a
// shared exponent) so texture filtering blends about like radiance. src/assets/rgbm.cpp is the CPU twin.
const float RGBM_RANGE = 16.0;
vec4 encode_rgbm(vec3 c) {
    float m = clamp(ceil(max(max(c.r, c.g), c.b) / RGBM_RANGE * 255.0), 1.0, 255.0) / 255.0;
    return vec4(clamp(c / (m * RGBM_RANGE), 0.0, 1.0), m);
}
vec3 decode_rgbm(vec4 t) { return t.rgb * (t.a * RGBM_RANGE); }

// Tone mapping: HDR radiance to displayable 0..1 (look.tonemap; the order of its choices).
const int TONEMAP_CLIP = 0;      // clamp at 1
const int TONEMAP_SOFT = 1;      // unchanged up to 0.8, then an exponential shoulder toward 1
const int TONEMAP_REINHARD = 2;  // c / (1 + c)
const int TONEMAP_ACES = 3;      // Narkowicz's fit of the ACES filmic curve
const float SOFT_KNEE = 0.8;

vec3 tonemap(vec3 c, int op) {
    c = max(c, 0.0);
    if (op == TONEMAP_SOFT) {
        vec3 shoulder = SOFT_KNEE + (1.0 - SOFT_KNEE) * (1.0 - exp((SOFT_KNEE - c) / (1.0 - SOFT_KNEE)));
        return mix(c, shoulder, step(SOFT_KNEE, c));
    }
    if (op == TONEMAP_REINHARD) return c / (1.0 + c);
    if (op == TONEMAP_ACES) return clamp(c * (2.51 * c + 0.03) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
    return min(c, 1.0);
}

// The sRGB transfer function (IEC 61966-2-1), so an sRGB texel the sampler decoded comes out as it went in.
// The power 1/2.4 is fitted with three square roots (Ian Taylor's fit, via chilliant.com "sRGB
// approximations"): at most 0.25/255 from the exact curve, every 8-bit value round-trips, and square roots
// cost a fraction of pow's log and exp (the exact form was half the puddle pass on llvmpipe).
vec3 encode_srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    vec3 s1 = sqrt(c), s2 = sqrt(s1), s3 = sqrt(s2);
    vec3 curve = 0.662002687 * s1 + 0.684122060 * s2 - 0.323583601 * s3 - 0.0225411470 * c;
    return mix(12.92 * c, curve, step(0.0031308, c));
}
