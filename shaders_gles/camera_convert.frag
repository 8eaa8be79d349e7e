#version 300 es
// A camera frame to colour, one output texel per camera pixel (output row y = camera row y, top first).
// The layout is chosen by #define:
//   LAYOUT_YUYV:   u_plane0 is RGBA8, one texel per two pixels (Y0 U Y1 V);
//   LAYOUT_NV12:   u_plane0 is the R8 Y plane, u_plane1 the RG8 UV plane at half size;
//   EXTERNAL_OES:  u_external is an EGLImage; the driver's sampler does any YUV conversion.
// YUV goes through the matrix and range the driver reported (u_yuv_matrix, u_yuv_offset). The target is
// sRGB, so the shader writes linear light and the hardware encodes it again.
#ifdef EXTERNAL_OES
#extension GL_OES_EGL_image_external_essl3 : require
#endif
precision highp float;

#include "srgb.glsl"

out vec4 o_color;

#ifdef EXTERNAL_OES
uniform samplerExternalOES u_external;
uniform vec2 u_size;  // camera pixels
#else
uniform sampler2D u_plane0;
uniform sampler2D u_plane1;
uniform mat3 u_yuv_matrix;
uniform vec3 u_yuv_offset;
#endif

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#if defined(EXTERNAL_OES)
    vec3 encoded = texture(u_external, (vec2(p) + 0.5) / u_size).rgb;
#else
#if defined(LAYOUT_YUYV)
    vec4 pair = texelFetch(u_plane0, ivec2(p.x / 2, p.y), 0);
    vec3 yuv = vec3((p.x & 1) == 0 ? pair.r : pair.b, pair.g, pair.a);
#else
    float y = texelFetch(u_plane0, p, 0).r;
    vec2 uv = texelFetch(u_plane1, p / 2, 0).rg;
    vec3 yuv = vec3(y, uv);
#endif
    vec3 encoded = clamp(u_yuv_matrix * (yuv - u_yuv_offset), 0.0, 1.0);
#endif
    o_color = vec4(srgb_to_linear(encoded), 1.0);
}
