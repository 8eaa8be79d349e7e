// A drop's impulse on the capillary field: a drop of diameter d (mm) t seconds after it hit pushes the
// water by a zero-mean ring profile (the 2D Laplacian of a Gaussian, whose radius follows the drop) times
// a few cycles of a sine under a sin^2 window, lower for bigger drops. A zero-mean push leaves no lasting
// dent, so the centre is calm once the train has left; the few cycles make the train of rings.
uniform vec4 u_drop_shape;  // texel size in mm, drop gain (height units per pass at the peak), seconds this
                            // pass ends before the step (<= 0, added to u_drops' ages), 0

// The push at the centre, in height units this pass (0 before the hit and after the few cycles).
float drop_push(float d, float t) {
    float f = 20.0 * sqrt(2.0 / d);  // Hz
    float duration = 3.0 / f;        // three cycles
    if (t < 0.0 || t >= duration) return 0.0;
    float window = sin(3.14159265 * t / duration);
    float size = d * 0.5;
    return u_drop_shape.y * size * sqrt(size) * window * window * sin(6.2831853 * f * t);
}
float drop_radius_texels(float d) { return max(1.5 * d / u_drop_shape.x, 1.2); }

// The 2D Laplacian of a Gaussian, zero-mean in the plane, at q = r^2 / radius^2; nothing past 3 radii.
float ring_profile(float q) { return q > 9.0 ? 0.0 : (1.0 - 0.5 * q) * exp(-0.5 * q); }
