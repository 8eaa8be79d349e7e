// The steady-state frame loop allocates nothing: global operator new/delete are replaced in
// this executable by counting ones, and a few hundred headless frames after a warm-up must count zero.
// The binary's own loop adds live tuning and the --stats ring buffer, so both run here too; remote
// control runs connected to a real broker, its network thread counted too.
//
// Only C++ allocations are counted (operator new, which our code, the standard library, spdlog and fmt
// go through); Mesa's own C allocations inside the GL driver are the driver's business.
#include <execinfo.h>
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <thread>

#include "params/config_loader.hpp"
#include "support/gpu_fixture.hpp"
#include "support/mosquitto_broker.hpp"
#include "systems/common/frame_stats.hpp"
#include "systems/display/display_power.hpp"
#include "systems/output/adaptive_scale.hpp"
#include "systems/puddle/puddle_plugin.hpp"
#include "systems/remote/remote_plugin.hpp"
#include "systems/tuning/live_tuning.hpp"
#include "systems/tuning/schedule_system.hpp"

namespace {

std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
// The first few allocating call stacks, printed when the test fails.
constexpr int max_traces = 6, max_depth = 24;
std::array<std::array<void*, max_depth>, max_traces> traces{};
std::array<int, max_traces> depths{};
thread_local bool in_hook = false;

void note_allocation() {
    if (!counting.load(std::memory_order_relaxed) || in_hook) return;
    const long n = allocations.fetch_add(1);
    if (n < max_traces) {
        in_hook = true;
        depths[static_cast<std::size_t>(n)] =
            backtrace(traces[static_cast<std::size_t>(n)].data(), max_depth);
        in_hook = false;
    }
}

void* counted(std::size_t size, std::size_t align = 0) {
    note_allocation();
    void* p = nullptr;
    if (align > alignof(std::max_align_t)) {
        if (posix_memalign(&p, align, size ? size : 1) != 0) p = nullptr;
    } else {
        p = std::malloc(size ? size : 1);
    }
    return p;
}

}  // namespace

void* operator new(std::size_t n) {
    if (void* p = counted(n)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
    return operator new(n);
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    return counted(n);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    return counted(n);
}
void* operator new(std::size_t n, std::align_val_t a) {
    if (void* p = counted(n, static_cast<std::size_t>(a))) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t n, std::align_val_t a) {
    return operator new(n, a);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}

namespace puddle::test {
namespace {

// Counts operator new calls while alive.
class AllocationCount {
public:
    AllocationCount() {
        allocations = 0;
        counting = true;
    }
    ~AllocationCount() { counting = false; }
    long stop() {
        counting = false;
        return allocations.load();
    }
};

void print_traces(long count) {
    for (long i = 0; i < std::min<long>(count, max_traces); ++i) {
        std::fprintf(stderr, "--- allocation %ld:\n", i + 1);
        backtrace_symbols_fd(traces[static_cast<std::size_t>(i)].data(), depths[static_cast<std::size_t>(i)],
                             2);
    }
}

constexpr int warm_up_frames = 30, counted_frames = 300;

void expect_no_allocation_in_frames(app::Engine& engine, systems::FrameStats& stats) {
    void* probe[1];
    backtrace(probe, 1);  // loads libgcc's unwinder now, not inside the hook
    for (int n = 0; n < warm_up_frames; ++n) ASSERT_TRUE(engine.frame(1.0 / 60.0).ok());
    AllocationCount count;
    for (int n = 0; n < counted_frames; ++n) {
        stats.tick();
        ASSERT_TRUE(engine.frame(1.0 / 60.0).ok());
        if (auto report = stats.take_report()) {
            EXPECT_GT(report->frames, 0u);
        }
    }
    const long allocated = count.stop();
    if (allocated) print_traces(allocated);
    EXPECT_EQ(allocated, 0) << "heap allocations in " << counted_frames
                            << " steady-state frames (stacks on stderr)";
}

TEST(FrameAllocation, TheCounterSeesAllocations) {  // else a zero below would prove nothing
    AllocationCount count;
    auto text = std::make_unique<std::string>(100, 'x');
    EXPECT_EQ(count.stop(), 2);
}

TEST(FrameAllocation, SteadyStateFramesAllocateNothing) {
    auto engine = make_engine(params::Params{}, {160, 90});
    ASSERT_TRUE(engine);
    systems::FrameStats stats(0.5);
    expect_no_allocation_in_frames(*engine, stats);
}

// The adaptive scale times every frame (GPU timer queries on llvmpipe) and decides every tenth of a second
// here; a 1 fps target is always met, so the scale stays and no canvas is remade in the counted frames.
TEST(FrameAllocation, SteadyStateFramesWithTheAdaptiveScaleAllocateNothing) {
    auto engine = make_engine(make_params({"render.target_fps=1"}), {160, 90});
    ASSERT_TRUE(engine);
    auto& adaptive = engine->world().resource<systems::AdaptiveScale>();
    adaptive.timing.hold_s = 0.1;
    systems::FrameStats stats(0.5);
    expect_no_allocation_in_frames(*engine, stats);
    ASSERT_TRUE(adaptive.controller.has_value());
    EXPECT_GT(adaptive.controller->last_cost_s(), 0.0) << "it measured frames and decided";
}

TEST(FrameAllocation, SteadyStateFramesWithLiveTuningAllocateNothing) {
    platform::DisplayOptions display;
    display.backend = platform::BackendKind::Headless;
    display.size = {160, 90};
    auto engine =
        app::Engine::create(params::Params{}, display, {},
                            {[](ecs::World& world, ecs::Schedule& schedule) {
                                 return systems::add_live_tuning(
                                     world, schedule, systems::LiveTuning(params::ParamLayers({}, {})));
                             },
                             systems::add_puddle_plugin});
    ASSERT_TRUE(engine.ok()) << engine.error().message;
    systems::FrameStats stats(0.5);
    expect_no_allocation_in_frames(**engine, stats);
}

// The schedule checks its cached next transition each frame and nothing more; an active entry's
// brightness adds the output canvas's dimming pass.
TEST(FrameAllocation, SteadyStateFramesWithAScheduleAllocateNothing) {
    platform::DisplayOptions display;
    display.backend = platform::BackendKind::Headless;
    display.size = {160, 90};
    auto config = params::parse_config(
        "[[schedule]]\nfrom = \"00:00\"\nto = \"24:00\"\nbrightness = 0.5\n[[schedule]]\nat = \"12:00\"\n"
        "set = { \"rain.intensity\" = 0.8 }\n",
        "alloc.toml");
    ASSERT_TRUE(config) << config.error().message;
    systems::LiveTuning tuning(params::ParamLayers({}, {}));
    ASSERT_TRUE(tuning.layers.set_config(std::move(*config)));
    auto engine =
        app::Engine::create(params::Params{}, display, {},
                            {systems::add_schedule,
                             [&](ecs::World& world, ecs::Schedule& schedule) {
                                 return systems::add_live_tuning(world, schedule, std::move(tuning));
                             },
                             systems::add_display_power, systems::add_puddle_plugin});
    ASSERT_TRUE(engine.ok()) << engine.error().message;
    (*engine)->world().resource<systems::WallClock>().now_ns = [] {
        return std::int64_t{1'780'000'000 + 3600} * systems::ns_per_second;
    };
    systems::FrameStats stats(0.5);
    expect_no_allocation_in_frames(**engine, stats);
    EXPECT_FLOAT_EQ((*engine)->params().get<params::ParamId::display_brightness>(), 0.5f);
}

// Remote control connected to a broker: after the first publishes, a frame with nothing arriving drains
// an empty queue and compares revisions, and allocates nothing (health is due once an hour here).
TEST(FrameAllocation, SteadyStateFramesWithRemoteControlAllocateNothing) {
    if (!mosquitto_available()) GTEST_SKIP() << no_mosquitto;
    MosquittoBroker broker;
    ASSERT_TRUE(broker.running()) << broker.log();
    params::Params p;
    using params::ParamId, params::ParamSource;
    p.set<ParamId::remote_enabled>(true, ParamSource::Config);
    p.set<ParamId::remote_port>(broker.port(), ParamSource::Config);
    p.set<ParamId::remote_prefix>("puddle/alloc", ParamSource::Config);
    p.set<ParamId::remote_health_interval>(3600.0f, ParamSource::Config);
    platform::DisplayOptions display;
    display.backend = platform::BackendKind::Headless;
    display.size = {160, 90};
    auto engine =
        app::Engine::create(p, display, {},
                            {[](ecs::World& world, ecs::Schedule& schedule) {
                                 return systems::add_live_tuning(
                                     world, schedule, systems::LiveTuning(params::ParamLayers({}, {})));
                             },
                             systems::add_puddle_plugin, systems::add_remote_plugin});
    ASSERT_TRUE(engine.ok()) << engine.error().message;
    const systems::RemoteControl& remote = (*engine)->world().resource<systems::RemoteControl>();
    for (int n = 0; n < 3000 && remote.connections_seen == 0; ++n) {
        ASSERT_TRUE((*engine)->frame(1.0 / 60.0).ok());
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_GT(remote.connections_seen, 0u) << "never connected to the broker";
    for (int n = 0; n < 20; ++n) {  // the state and discovery go out on the network thread
        ASSERT_TRUE((*engine)->frame(1.0 / 60.0).ok());
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    systems::FrameStats stats(0.5);
    expect_no_allocation_in_frames(**engine, stats);
}

TEST(FrameAllocation, StatsReportAllocatesNothing) {
    systems::FrameStats stats;
    for (int n = 0; n < 500; ++n) stats.add(0.016 + 0.001 * (n % 7), 0.002, 0.001);
    AllocationCount count;
    const systems::FrameStats::Summary s = stats.summary();
    EXPECT_EQ(count.stop(), 0);
    EXPECT_GT(s.p99_ms, s.p50_ms);
}

}  // namespace
}  // namespace puddle::test
