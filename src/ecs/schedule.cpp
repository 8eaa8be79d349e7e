#include "ecs/schedule.hpp"

namespace puddle::ecs {

std::string_view stage_name(Stage s) {
    switch (s) {
        case Stage::Input:
            return "input";
        case Stage::Simulate:
            return "simulate";
        case Stage::Render:
            return "render";
        case Stage::Present:
            return "present";
        case Stage::Exit:
            return "exit";
    }
    return "?";
}

Schedule::Entry& Schedule::add_entry(Stage stage, std::string name, System run, SystemAccess access) {
    auto& stage_entries = stages_[static_cast<std::size_t>(stage)];
    stage_entries.push_back(Entry(std::move(name), std::move(run), std::move(access)));
    return stage_entries.back();  // valid until the next registration: for chaining run_if
}

void Schedule::Entry::run(World& world) {
    for (RunCondition& c : conditions_)
        if (!c.test(world)) return;
    run_(world);
}

std::string Schedule::Entry::describe(Stage stage) const {
    std::string line = std::string(stage_name(stage)) + "/" + name_;
    for (std::size_t i = 0; i < conditions_.size(); ++i)
        line += (i == 0 ? " if " : " and ") + conditions_[i].name;
    auto join = [](const std::vector<std::string>& names) {
        std::string out;
        for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
        return out;
    };
    std::vector<std::string> parts;
    if (access_.world) parts.push_back("the world");
    if (!access_.reads.empty()) parts.push_back("reads " + join(access_.reads));
    if (!access_.writes.empty()) parts.push_back("writes " + join(access_.writes));
    if (!parts.empty()) {
        line += " (";
        for (std::size_t i = 0; i < parts.size(); ++i) line += (i == 0 ? "" : "; ") + parts[i];
        line += ")";
    }
    return line;
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

void Schedule::run_exit(World& world) {
    run_stage(Stage::Exit, world);
}

std::vector<std::string> Schedule::describe() const {
    std::vector<std::string> out;
    for (Stage s : all_stages)
        for (const Entry& e : stages_[static_cast<std::size_t>(s)]) out.push_back(e.describe(s));
    return out;
}

}  // namespace puddle::ecs
