#include "ecs/schedule.hpp"

namespace puddle::ecs {

std::string_view stage_name(Stage s) {
    switch (s) {
        case Stage::Input: return "input";
        case Stage::Simulate: return "simulate";
        case Stage::Render: return "render";
        case Stage::Present: return "present";
    }
    return "?";
}

void Schedule::add_system(Stage stage, std::string name, System system) {
    stages_[static_cast<std::size_t>(stage)].push_back({std::move(name), std::move(system)});
}

void Schedule::run_stage(Stage stage, World& world) {
    for (Entry& e : stages_[static_cast<std::size_t>(stage)]) e.run(world);
}

void Schedule::run_frame(World& world) {
    run_stage(Stage::Input, world);
    const int steps = step_counter_ ? step_counter_(world) : 1;
    for (int i = 0; i < steps; ++i) run_stage(Stage::Simulate, world);
    run_stage(Stage::Render, world);
    run_stage(Stage::Present, world);
}

std::vector<std::string> Schedule::describe() const {
    std::vector<std::string> out;
    for (Stage s : all_stages)
        for (const Entry& e : stages_[static_cast<std::size_t>(s)])
            out.push_back(std::string(stage_name(s)) + "/" + e.name);
    return out;
}

}  // namespace puddle::ecs
