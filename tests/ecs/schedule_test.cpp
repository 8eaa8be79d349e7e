// Tests for src/ecs/schedule.hpp: fixed stage order, the fixed-step simulate stage, registration order.
#include "ecs/schedule.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace puddle::ecs {
namespace {

// The log of what ran, kept in the World like any other state.
struct Trace {
    std::vector<std::string> calls;
};
struct StepsWanted {
    int n = 0;
};

System record(std::string name) {
    return [name = std::move(name)](World& w) { w.resource<Trace>().calls.push_back(name); };
}

class ScheduleTest : public ::testing::Test {
protected:
    void SetUp() override { world.insert_resource<Trace>(); }
    const std::vector<std::string>& calls() { return world.resource<Trace>().calls; }
    World world;
    Schedule schedule;
};

TEST_F(ScheduleTest, StagesRunInFixedOrderWhateverTheRegistrationOrder) {
    // Registered back to front on purpose.
    schedule.add_system(Stage::Present, "present", record("present"));
    schedule.add_system(Stage::Render, "render", record("render"));
    schedule.add_system(Stage::Simulate, "simulate", record("simulate"));
    schedule.add_system(Stage::Input, "input", record("input"));
    schedule.run_frame(world);
    EXPECT_EQ(calls(), (std::vector<std::string>{"input", "simulate", "render", "present"}));
}

TEST_F(ScheduleTest, SimulateRunsOnceWithoutAStepCounter) {
    schedule.add_system(Stage::Simulate, "sim", record("sim"));
    schedule.run_frame(world);
    schedule.run_frame(world);
    EXPECT_EQ(calls(), (std::vector<std::string>{"sim", "sim"}));
}

TEST_F(ScheduleTest, SimulateRunsAsOftenAsTheStepCounterSays) {
    schedule.add_system(Stage::Input, "input", record("input"));
    schedule.add_system(Stage::Simulate, "a", record("a"));
    schedule.add_system(Stage::Simulate, "b", record("b"));
    schedule.add_system(Stage::Render, "render", record("render"));
    schedule.add_system(Stage::Present, "present", record("present"));
    schedule.set_step_counter([](World&) { return 3; });
    schedule.run_frame(world);
    EXPECT_EQ(calls(),
              (std::vector<std::string>{"input", "a", "b", "a", "b", "a", "b", "render", "present"}));
}

TEST_F(ScheduleTest, StepCounterIsReadAfterTheInputStage) {
    world.insert_resource<StepsWanted>();
    // The input stage decides how many steps are due (as the frame clock does).
    schedule.add_system(Stage::Input, "clock", [](World& w) {
        w.resource<Trace>().calls.push_back("clock");
        w.resource<StepsWanted>().n += 1;
    });
    schedule.add_system(Stage::Simulate, "step", record("step"));
    schedule.add_system(Stage::Render, "render", record("render"));
    schedule.set_step_counter([](World& w) { return w.resource<StepsWanted>().n; });

    schedule.run_frame(world);  // 1 step
    schedule.run_frame(world);  // 2 steps
    EXPECT_EQ(calls(),
              (std::vector<std::string>{"clock", "step", "render", "clock", "step", "step", "render"}));
}

TEST_F(ScheduleTest, ZeroStepsSkipsSimulateButStillRendersAndPresents) {
    schedule.add_system(Stage::Input, "input", record("input"));
    schedule.add_system(Stage::Simulate, "sim", record("sim"));
    schedule.add_system(Stage::Render, "render", record("render"));
    schedule.add_system(Stage::Present, "present", record("present"));
    schedule.set_step_counter([](World&) { return 0; });
    schedule.run_frame(world);
    EXPECT_EQ(calls(), (std::vector<std::string>{"input", "render", "present"}));
}

TEST_F(ScheduleTest, SystemsInsideAStageRunInRegistrationOrder) {
    for (const char* n : {"third", "first", "second"}) schedule.add_system(Stage::Render, n, record(n));
    schedule.add_system(Stage::Input, "z", record("z"));
    schedule.add_system(Stage::Input, "y", record("y"));
    schedule.run_frame(world);
    EXPECT_EQ(calls(), (std::vector<std::string>{"z", "y", "third", "first", "second"}));
}

TEST_F(ScheduleTest, EmptyScheduleRunsNothing) {
    schedule.run_frame(world);
    EXPECT_TRUE(calls().empty());
    EXPECT_TRUE(schedule.describe().empty());
}

TEST_F(ScheduleTest, DescribeListsNamesInExecutionOrder) {
    schedule.add_system(Stage::Present, "swap", record("swap"));
    schedule.add_system(Stage::Simulate, "wave", record("wave"));
    schedule.add_system(Stage::Input, "clock", record("clock"));
    schedule.add_system(Stage::Simulate, "drops", record("drops"));
    schedule.add_system(Stage::Render, "surface", record("surface"));
    EXPECT_EQ(schedule.describe(),
              (std::vector<std::string>{"input/clock (the world)", "simulate/wave (the world)",
                                        "simulate/drops (the world)", "render/surface (the world)",
                                        "present/swap (the world)"}));
    // Describing runs nothing.
    EXPECT_TRUE(calls().empty());
}

TEST(StageName, NamesEveryStage) {
    EXPECT_EQ(stage_name(Stage::Input), "input");
    EXPECT_EQ(stage_name(Stage::Simulate), "simulate");
    EXPECT_EQ(stage_name(Stage::Render), "render");
    EXPECT_EQ(stage_name(Stage::Present), "present");
    EXPECT_EQ(stage_name(Stage::Exit), "exit");
    ASSERT_EQ(all_stages.size(), 5u);
    EXPECT_EQ(all_stages[0], Stage::Input);
    EXPECT_EQ(all_stages[1], Stage::Simulate);
    EXPECT_EQ(all_stages[2], Stage::Render);
    EXPECT_EQ(all_stages[3], Stage::Present);
    EXPECT_EQ(all_stages[4], Stage::Exit);
}

// --- systems as plain functions: parameters fetched by type -------------------------------------------

struct Speed {
    double metres_per_second = 0;
};
struct Position {
    double metres = 0;
};
struct Tick {
    double seconds = 0.5;
};

void move_system(const Speed& speed, const Tick& tick, Position& position) {
    position.metres += speed.metres_per_second * tick.seconds;
}
void spawn_system(World& world, const Speed&) {
    world.spawn();
}
void trace_system(Trace& trace) {
    trace.calls.push_back("trace");
}

TEST_F(ScheduleTest, APlainFunctionGetsItsResourcesByType) {
    world.insert_resource<Speed>(Speed{3.0});
    world.insert_resource<Tick>();
    world.insert_resource<Position>(Position{1.0});
    schedule.add(Stage::Simulate, "move", move_system);
    schedule.run_frame(world);
    schedule.run_frame(world);
    EXPECT_DOUBLE_EQ(world.resource<Position>().metres, 1.0 + 2 * 3.0 * 0.5);
    EXPECT_DOUBLE_EQ(world.resource<Speed>().metres_per_second, 3.0);  // read, not written
}

TEST_F(ScheduleTest, AResourceReplacedBetweenFramesIsTheOneFetched) {
    world.insert_resource<Speed>(Speed{1.0});
    world.insert_resource<Tick>(Tick{1.0});
    world.insert_resource<Position>();
    schedule.add(Stage::Simulate, "move", move_system);
    schedule.run_frame(world);
    world.insert_resource<Position>(Position{10.0});
    schedule.run_frame(world);
    EXPECT_DOUBLE_EQ(world.resource<Position>().metres, 11.0);
}

TEST_F(ScheduleTest, ASystemTakingTheWorldGetsIt) {
    world.insert_resource<Speed>();
    schedule.add(Stage::Input, "spawn", spawn_system);
    schedule.run_frame(world);
    schedule.run_frame(world);
    EXPECT_EQ(world.entity_count(), 2u);
}

TEST_F(ScheduleTest, DescribeNamesWhatEachSystemReadsAndWrites) {
    schedule.add(Stage::Simulate, "move", move_system);
    schedule.add(Stage::Input, "spawn", spawn_system);
    schedule.add(Stage::Present, "trace", trace_system).run_if({"never", [](World&) { return false; }});
    EXPECT_EQ(schedule.describe(), (std::vector<std::string>{
                                       "input/spawn (the world; reads Speed)",
                                       "simulate/move (reads Speed, Tick; writes Position)",
                                       "present/trace if never (writes Trace)",
                                   }));
}

TEST_F(ScheduleTest, RunConditionsAreCheckedEveryRunAndAllMustHold) {
    struct Gate {
        bool open = false;
        bool second = true;
    };
    world.insert_resource<Gate>();
    schedule.add(Stage::Render, "trace", trace_system)
        .run_if({"gate open", [](World& w) { return w.resource<Gate>().open; }})
        .run_if({"second open", [](World& w) { return w.resource<Gate>().second; }});
    schedule.run_frame(world);
    EXPECT_TRUE(calls().empty());
    world.resource<Gate>().open = true;
    schedule.run_frame(world);
    EXPECT_EQ(calls().size(), 1u);
    world.resource<Gate>().second = false;
    schedule.run_frame(world);
    EXPECT_EQ(calls().size(), 1u);
    EXPECT_EQ(schedule.describe(),
              (std::vector<std::string>{"render/trace if gate open and second open (writes Trace)"}));
}

TEST_F(ScheduleTest, TheExitStageRunsOnlyWhenAskedAndOnce) {
    schedule.add_system(Stage::Input, "input", record("input"));
    schedule.add_system(Stage::Exit, "save", record("save"));
    schedule.run_frame(world);
    schedule.run_frame(world);
    EXPECT_EQ(calls(), (std::vector<std::string>{"input", "input"}));
    schedule.run_exit(world);
    EXPECT_EQ(calls(), (std::vector<std::string>{"input", "input", "save"}));
}

}  // namespace
}  // namespace puddle::ecs
