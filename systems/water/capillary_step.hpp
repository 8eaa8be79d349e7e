#pragma once
// The factors of one capillary wave step (shaders_gles/wave_step.frag, CAPILLARY) and how many such
// steps a fixed simulation step takes, from the physical parameters. The equation, in metres and seconds:
//   h_tt = c^2 lap(h) - beta lap(lap(h)) + 2 nu lap(h_t) - drag h_t - w0^2 h
// (c: wave.ring_speed, beta: wave.dispersion, nu: wave.viscosity, drag: wave.drag; plane waves obey
// w^2 = c^2 k^2 + beta k^4 + w0^2, and their amplitude fades at nu k^2 + drag / 2 a second (Lamb,
// Hydrodynamics, sections 266 and 348; his deep-water rate is 2 nu k^2, so nu here is twice the physical).
// The last term returns the water to its level: the impulses, zero-mean in the plane, leave a little net
// volume once sampled on texels, and without it the field's mean would wander for ever (and screens of a
// wall, which forget their past by damping, would never agree). w0 = 2 rad/s is far below any ripple's
// frequency (about 85 rad/s at 1.7 cm), so the rings are as before. The explicit leapfrog is stable while
// dt^2 (8 c^2 / dx^2 + 64 beta / dx^4) < 4 (the checkerboard mode's eigenvalues of the 5- and 13-point
// stencils) and 16 nu dt / dx^2 < 1; substeps keeps both under 70% of the limit.

#include "params/param_store.hpp"

namespace puddle::systems {

// Heights of the capillary field are in units of 0.1 mm: the ripples are fractions of a millimetre,
// which keeps them well inside the RG32I fallback's and the RGBA8 surface's ranges.
inline constexpr double capillary_height_unit_m = 1e-4;

// w0 of the level term, rad/s.
inline constexpr double capillary_level_rad_s = 2.0;

struct CapillaryStep {
    int substeps = 1;      // wave passes per fixed simulation step
    double dt = 0.0;       // seconds per pass
    double texel_m = 0.0;  // dx: wave.size / wave.resolution
    float a = 0.0f;        // c^2 dt^2 / dx^2
    float b = 0.0f;        // beta dt^2 / dx^4
    float v = 0.0f;        // 2 nu dt / dx^2
    float keep = 1.0f;     // 1 - drag dt: the share of the last pass's motion kept
    float level = 0.0f;    // w0^2 dt^2
};

// For a fixed step of step_seconds at these parameters (wave.resolution, wave.size and the rest).
CapillaryStep capillary_step(const params::Params& params, double step_seconds);

}  // namespace puddle::systems
