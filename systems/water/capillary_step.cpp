#include "systems/water/capillary_step.hpp"

#include <algorithm>
#include <cmath>

namespace puddle::systems {

using params::ParamId;

CapillaryStep capillary_step(const params::Params& params, double step_seconds) {
    const double dx =
        static_cast<double>(params.get<ParamId::wave_size>()) / params.get<ParamId::wave_resolution>();
    const double c = static_cast<double>(params.get<ParamId::wave_ring_speed>());
    const double beta = static_cast<double>(params.get<ParamId::wave_dispersion>()) * 1e-8;  // cm^4 to m^4
    const double nu = static_cast<double>(params.get<ParamId::wave_viscosity>()) * 1e-4;     // cm^2 to m^2
    const double drag = static_cast<double>(params.get<ParamId::wave_drag>());
    constexpr double margin = 0.7;
    const double wave_limit =
        margin * 2.0 / std::sqrt(8.0 * c * c / (dx * dx) + 64.0 * beta / (dx * dx * dx * dx));
    const double viscous_limit = nu > 0.0 ? margin * dx * dx / (16.0 * nu) : wave_limit;
    const double limit = std::min(wave_limit, viscous_limit);
    CapillaryStep s;
    s.substeps = std::max(1, static_cast<int>(std::ceil(step_seconds / limit)));
    s.dt = step_seconds / s.substeps;
    s.texel_m = dx;
    s.a = static_cast<float>(c * c * s.dt * s.dt / (dx * dx));
    s.b = static_cast<float>(beta * s.dt * s.dt / (dx * dx * dx * dx));
    s.v = static_cast<float>(2.0 * nu * s.dt / (dx * dx));
    s.keep = static_cast<float>(std::max(0.0, 1.0 - drag * s.dt));
    s.level = static_cast<float>(capillary_level_rad_s * capillary_level_rad_s * s.dt * s.dt);
    return s;
}

}  // namespace puddle::systems
