#pragma once
// The Schedule: named stages run in a fixed order each frame. Systems are plain functions over the
// World; the order inside a stage is the order of registration, written in one place
// (systems/puddle_plugin.cpp). The simulate stage is a fixed-step stage: it runs once per simulation
// step due this frame (FrameClock::steps_due), never once per displayed frame.

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ecs/world.hpp"

namespace puddle::ecs {

enum class Stage { Input, Simulate, Render, Present };
inline constexpr std::array all_stages{Stage::Input, Stage::Simulate, Stage::Render, Stage::Present};
std::string_view stage_name(Stage s);

using System = std::function<void(World&)>;
// Returns how many times the simulate stage runs this frame (read after the input stage).
using StepCounter = std::function<int(World&)>;

class Schedule {
public:
    void add_system(Stage stage, std::string name, System system);
    void set_step_counter(StepCounter counter) { step_counter_ = std::move(counter); }
    void run_frame(World& world);
    // System names in execution order, for logs and tests.
    std::vector<std::string> describe() const;

private:
    struct Entry {
        std::string name;
        System run;
    };
    void run_stage(Stage stage, World& world);
    std::array<std::vector<Entry>, all_stages.size()> stages_;
    StepCounter step_counter_;
};

}  // namespace puddle::ecs
