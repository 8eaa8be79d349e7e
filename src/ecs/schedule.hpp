#pragma once
// The Schedule: named stages run in a fixed order each frame. Systems are plain functions over the
// World's resources (ecs/system_params.hpp: `const T&` reads, `T&` writes); each feature registers its
// systems in one place, its plugin, in the order they run inside a stage, with a run condition where
// the system only sometimes applies (Bevy's `.run_if`). The simulate stage is a fixed-step stage: it
// runs once per simulation step due this frame (the step counter), never once per displayed frame.
// The exit stage runs once, when the program stops (run_exit), not in frames.

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ecs/system_params.hpp"
#include "ecs/world.hpp"

namespace puddle::ecs {

enum class Stage { Input, Simulate, Render, Present, Exit };
inline constexpr std::array all_stages{Stage::Input, Stage::Simulate, Stage::Render, Stage::Present,
                                       Stage::Exit};
std::string_view stage_name(Stage s);

using System = std::function<void(World&)>;
// Returns how many times the simulate stage runs this frame (read after the input stage).
using StepCounter = std::function<int(World&)>;

// A named test run before a system each time; false skips the system for this run.
struct RunCondition {
    std::string name;  // for describe(): "look is ocean"
    std::function<bool(World&)> test;
};

class Schedule {
public:
    class Entry;

    // Registers a plain function whose parameters are fetched from the World by type.
    template <class Result, class... Params>
    Entry& add(Stage stage, std::string name, Result (*fn)(Params...)) {
        return add_entry(
            stage, std::move(name), [fn](World& w) { call_with_resources(fn, w); }, access_of(fn));
    }
    // Registers a closure over the World (tests, and systems that need state of their own).
    Entry& add_system(Stage stage, std::string name, System system) {
        SystemAccess access;
        access.world = true;
        return add_entry(stage, std::move(name), std::move(system), std::move(access));
    }
    void set_step_counter(StepCounter counter) { step_counter_ = std::move(counter); }
    // Input, the due simulate steps, render, present.
    void run_frame(World& world);
    // The exit stage (saves, last messages), once.
    void run_exit(World& world);
    // One stage once, alone (the benchmark times the simulate stage this way).
    void run_stage(Stage stage, World& world);
    // One line per system in execution order: "render/ocean if look is ocean (reads Params, FrameClock;
    // writes Device, OceanRenderer)". Logged at debug level at start-up; a test pins the engine's.
    std::vector<std::string> describe() const;

    class Entry {
    public:
        // Runs the system only while `condition` holds (checked each run). Conditions add up (all must hold).
        Entry& run_if(RunCondition condition) {
            conditions_.push_back(std::move(condition));
            return *this;
        }

    private:
        friend class Schedule;
        Entry(std::string name, System run, SystemAccess access)
            : name_(std::move(name)), run_(std::move(run)), access_(std::move(access)) {}
        void run(World& world);
        std::string describe(Stage stage) const;
        std::string name_;
        System run_;
        SystemAccess access_;
        std::vector<RunCondition> conditions_;
    };

private:
    Entry& add_entry(Stage stage, std::string name, System run, SystemAccess access);
    std::array<std::vector<Entry>, all_stages.size()> stages_;
    StepCounter step_counter_;
};

}  // namespace puddle::ecs
