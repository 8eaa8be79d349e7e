// How the surface texture stores (height, hL - hR, hD - hU). Float targets store values as they are;
// the RGBA8 fallback (SURFACE_UNORM) maps [-SURFACE_RANGE, SURFACE_RANGE] to [0, 1].
#ifdef SURFACE_UNORM
const float SURFACE_RANGE = 4.0;
vec3 encode_surface(vec3 v) { return clamp(v / SURFACE_RANGE * 0.5 + 0.5, 0.0, 1.0); }
vec3 decode_surface(vec3 s) { return (s * 2.0 - 1.0) * SURFACE_RANGE; }
#else
vec3 encode_surface(vec3 v) { return v; }
vec3 decode_surface(vec3 s) { return s; }
#endif
