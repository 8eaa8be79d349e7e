#version 300 es
// Analytic ripples (REFERENCE.md section 4): every live source summed in closed form into the surface the
// puddle render reads (height, hL - hR, hD - hU; see surface.frag). At distance d and age tau, with
// x = tau - d / v:
//   W = A / (1 + l1 d^2 + l2 tau^2) * cos(Omega / (1 + l3 tau) * x - pi/2)   where x > 0, phase < maximum.
// The slopes come from the derivative of W, not from more evaluations: one term per source per texel.
precision highp float;
precision highp int;

#include "surface_encoding.glsl"

// Three texels per source, row = source; the first alone decides whether the front has arrived, so
// the many texels a young source has not reached yet cost one fetch:
//   (x, y in texels, age tau in s, speed v), (l1, l2, l3, Omega), (amplitude A, maximum phase, 0, 0)
uniform highp sampler2D u_sources;
uniform int u_source_count;

out vec4 o_surface;

void main() {
    vec2 p = gl_FragCoord.xy;
    float h = 0.0;
    vec2 gradient = vec2(0.0);
    for (int i = 0; i < u_source_count; ++i) {
        vec4 a = texelFetch(u_sources, ivec2(0, i), 0);
        vec2 delta = p - a.xy;
        float d = length(delta);
        float tau = a.z;
        float v = a.w;
        float x = tau - d / v;
        if (x <= 0.0) continue;  // the front has not arrived
        vec4 b = texelFetch(u_sources, ivec2(1, i), 0);
        vec4 c = texelFetch(u_sources, ivec2(2, i), 0);
        float omega = b.w / (1.0 + b.z * tau);
        float phase = omega * x;
        if (phase >= c.y) continue;  // past the ring count
        float g = 1.0 / (1.0 + b.x * d * d + b.y * tau * tau);
        float s = sin(phase);  // cos(phase - pi/2)
        h += c.x * g * s;
        // dW/dd = A * (dg/dd * sin + g * cos * dphase/dd), dg/dd = -2 l1 d g^2, dphase/dd = -omega / v.
        float dw = c.x * (-2.0 * b.x * d * g * g * s - g * cos(phase) * omega / v);
        gradient += dw * delta / max(d, 1e-4);
    }
    // Central differences one texel apart, as surface.frag stores them: hL - hR = -2 dh/dx.
    o_surface = vec4(encode_surface(vec3(h, -2.0 * gradient)), 0.0);  // alpha: no splashes (surface.frag)
}
