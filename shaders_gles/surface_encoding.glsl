// How the surface texture stores (height, hL - hR, hD - hU). Float targets store values as they are;
// the RGBA8 fallback (SURFACE_UNORM) maps [-SURFACE_RANGE, SURFACE_RANGE] to the bytes [1, 255] with zero
// on byte 128 exactly, so still water decodes flat (a 0.5 midpoint is no byte: it stored 128 and read
// back a slope that tilted every normal).
#ifdef SURFACE_UNORM
const float SURFACE_RANGE = 4.0;
vec3 encode_surface(vec3 v) { return clamp((v / SURFACE_RANGE * 127.0 + 128.0) / 255.0, 0.0, 1.0); }
vec3 decode_surface(vec3 s) { return (s * 255.0 - 128.0) / 127.0 * SURFACE_RANGE; }
#else
vec3 encode_surface(vec3 v) { return v; }
vec3 decode_surface(vec3 s) { return s; }
#endif
