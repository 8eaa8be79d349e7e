#include "systems/street/street_system.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/shader_hash.hpp"
#include "render/shader_phase.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {
gpu::PipelineDesc street_desc() {
    return {.label = "street", .vertex = "view_window.vert", .fragment = "street.frag"};
}

// Source i of a kind: its period and phase offset from integer hashes of (i, salt, seed), as street.frag
// drew them, then its repeat and age at `seconds`.
void set_sources(const StreetSourceKind& kind, std::uint32_t seed, double seconds,
                 std::array<float, street_max_sources>& ages, std::array<int, street_max_sources>& repeats) {
    for (std::uint32_t i = 0; i < street_max_sources; ++i) {
        const double u = render::shader_unit_float(render::shader_hash3(i, kind.salt, seed));
        const double period = kind.min_period + (kind.max_period - kind.min_period) * u;
        const double offset = render::shader_unit_float(render::shader_hash3(i, kind.salt + 1u, seed));
        const render::Repetition r = render::repetition_at(seconds, period, offset);
        ages[i] = r.age;
        repeats[i] = static_cast<int>(r.index);  // the shader takes the bits back as a uint
    }
}
}  // namespace

glm::vec2 street_source_spot(const StreetSourceKind& kind, int i, int repeat, float horizon_f,
                             float aspect_f) {
    const double horizon = horizon_f, aspect = aspect_f;
    const auto id = static_cast<std::uint32_t>(i), at = static_cast<std::uint32_t>(repeat);
    const double x = render::shader_unit_float(render::shader_hash3(id, at, kind.salt + 2u));
    const double y = render::shader_unit_float(render::shader_hash3(id, at, kind.salt + 3u)) * horizon * 0.9;
    const double depth = std::max((horizon - y) / horizon, 1e-3);
    return {static_cast<float>((x - 0.5) * aspect / depth * 0.3), static_cast<float>(0.3 / depth)};
}

StreetTime street_time(const params::Params& params, double seconds, float aspect) {
    constexpr double two_pi = 2.0 * std::numbers::pi;
    StreetTime st;
    // sin(1.7 t + 3) * sin(2.3 t): the constant 3 rides in the phase, reduced with it.
    st.lightning_phase = {render::periodic_phase(seconds + 3.0 / 1.7, 1.7, two_pi),
                          render::periodic_phase(seconds, 2.3, two_pi)};
    // The clouds drift street.cloud_drift screens per second; the fbm's octave i samples 3 * 2.03^i
    // cells per screen.
    const double cloud_drift = params.get<ParamId::street_cloud_drift>();
    double cells_per_screen = 3.0;
    for (std::size_t i = 0; i < st.cloud_shift.size(); ++i, cells_per_screen *= 2.03) {
        const render::LatticeShift shift = render::lattice_shift(seconds, cloud_drift * cells_per_screen);
        st.cloud_shift[i] = shift.fraction;
        st.cloud_cells[i] = shift.cells;
    }
    // The ground drifts street.ground_drift units per second under noises of 4, 8 and 40 cells per unit.
    const double drift = params.get<ParamId::street_ground_drift>();
    constexpr std::array<double, 3> ground_cells_per_unit{4.0, 8.0, 40.0};
    for (int i = 0; i < 3; ++i) {
        const render::LatticeShift shift =
            render::lattice_shift(seconds, ground_cells_per_unit[static_cast<std::size_t>(i)] * drift);
        st.ground_shift[i] = shift.fraction;
        st.ground_cells[static_cast<std::size_t>(i)] = shift.cells;
    }
    // The facades and lamps drift with the ground (street.ground_drift units a second), in whole units.
    const render::LatticeShift street = render::lattice_shift(seconds, drift);
    st.street_shift = street.fraction;
    st.street_cells = street.cells;
    const int lamps = params.get<ParamId::street_lamps>();
    for (int i = 0; i < street_max_lamps; ++i)
        st.lamps[static_cast<std::size_t>(i)] = street_lamp(i, lamps, street.fraction);
    const auto seed = static_cast<std::uint32_t>(params.get<ParamId::rain_seed>());
    set_sources(street_ripple_kind, seed, seconds, st.ripple_age, st.ripple_repeat);
    set_sources(street_splash_kind, seed, seconds, st.splash_age, st.splash_repeat);
    // What the shader draws of each: two rings growing at street.ripple_speed, fading in over 0.3 s and
    // out as exp(-1.5 age); a splash's ring at street.splash_speed, fading as exp(-4 age).
    const float horizon = params.get<ParamId::street_horizon>();
    const double ripple_speed = params.get<ParamId::street_ripple_speed>();
    const double splash_speed = params.get<ParamId::street_splash_speed>();
    for (std::size_t i = 0; i < street_max_sources; ++i) {
        const double age = st.ripple_age[i];
        const double fade_in = std::clamp(age / 0.3, 0.0, 1.0);
        const glm::vec2 spot =
            street_source_spot(street_ripple_kind, static_cast<int>(i), st.ripple_repeat[i], horizon, aspect);
        st.ripples[i] = {spot, static_cast<float>(ripple_speed * age),
                         static_cast<float>(std::exp(-1.5 * age) * fade_in * fade_in * (3 - 2 * fade_in))};
        const glm::vec2 splash =
            street_source_spot(street_splash_kind, static_cast<int>(i), st.splash_repeat[i], horizon, aspect);
        const double splash_age = st.splash_age[i];
        st.splashes[i] = {splash, static_cast<float>(splash_speed * splash_age),
                          static_cast<float>(std::exp(-4.0 * splash_age))};
    }
    return st;
}

glm::vec4 street_lamp(int i, int count, double shift) {
    const double z = i + 1 - shift;
    auto smoothstep = [](double a, double b, double x) {
        const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
        return t * t * (3 - 2 * t);
    };
    const double shown = smoothstep(0.15, 0.45, z) * (1 - smoothstep(count - 1.5, count, z));
    const double size = 0.006 / z;
    return {static_cast<float>(z), static_cast<float>(1 / z), static_cast<float>(size * size),
            static_cast<float>(shown)};
}

StreetRenderer::StreetRenderer() : pass(street_desc()) {}

void street_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                   StreetRenderer& street, const RenderTarget& target) {
    street.pass.draw(device, params, target, gpu::LoadOp::DontCare, [&](gpu::RenderPass& pass) {
        const float aspect = target.view.view_aspect(target.target.size);
        const StreetTime st = street_time(params, clock.sim_time, aspect);
        pass.set("u_aspect", aspect)
            .set("u_lightning_phase", st.lightning_phase)
            .set("u_cloud_shift", std::span<const float>(st.cloud_shift))
            .set("u_cloud_cells", std::span<const int>(st.cloud_cells))
            .set("u_noise_shift", st.ground_shift)
            .set("u_noise_cells", std::span<const int>(st.ground_cells))
            .set("u_drift_shift", st.street_shift)
            .set("u_drift_cells", st.street_cells)
            .set("u_lamp", std::span<const glm::vec4>(st.lamps))
            .set("u_ripple", std::span<const glm::vec4>(st.ripples))
            .set("u_splash", std::span<const glm::vec4>(st.splashes));
    });
}

void add_street_plugin(ecs::World& world, ecs::Schedule& schedule) {
    auto& street = world.insert_resource<StreetRenderer>();
    world.resource<Looks>().entries.push_back(fullscreen_look(Scene::street, street.pass));
    schedule.add(ecs::Stage::Render, "street", street_system)
        .run_if(look_is(Scene::street))
        .run_if(output_on());
}

}  // namespace puddle::systems
