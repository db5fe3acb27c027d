// [simulation] time = T instead of steps: the reader's rules, the steps that reach T, and
// a run that ends at the first step at or past T.
#include "core/particle_model.hpp"
#include "core/time_step.hpp"
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"
#include "tridem/run.hpp"
#include "tridem/scene_io.hpp"
#include "unit/io/io_test_support.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

std::string scene_with(const std::string& length) {
  return fmt::format(R"(
[simulation]
{}
[[material]]
name = "m"
density = 1000.0
penalty = 1e6
[[triangle]]
material = "m"
vertices = [[0, 0], [1, 0], [0, 1]]
)",
                     length);
}

void expect_refused(const std::string& length, const std::string& words) {
  try {
    (void)parse_scene(scene_with(length), "t.toml");
    FAIL() << "accepted: " << length;
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(RunLength, TimeIsReadInsteadOfSteps) {
  const Scene s = parse_scene(scene_with("time = 0.25"), "t.toml");
  EXPECT_EQ(s.simulation.duration, 0.25);
  EXPECT_EQ(s.simulation.steps, 0);
  EXPECT_EQ(parse_scene(scene_with("steps = 7"), "t.toml").simulation.steps, 7);
}

TEST(RunLength, OneOfStepsAndTimeIsRequired) {
  expect_refused("steps = 10\ntime = 1.0", "give one of them");
  expect_refused("gravity = [0, -9.81]", "or give time");
  expect_refused("time = 0.0", "time");
  expect_refused("time = -1.0", "time");
  expect_refused("time = nan", "time");
}

TEST(RunLength, StepsReachTheTime) {
  SimulationSettings s;
  s.duration = 1.0;
  EXPECT_EQ(steps_to_reach(s, 0.3), 4) << "3 steps end at 0.9 s, short of 1 s";
  EXPECT_EQ(steps_to_reach(s, 0.1), 10) << "1/0.1 is 10 within rounding, not 11";
  EXPECT_EQ(steps_to_reach(s, 2.0), 1);
  s.duration = 1e10;
  EXPECT_THROW((void)steps_to_reach(s, 1e-9), RunError);
  SimulationSettings by_steps;
  by_steps.steps = 42;
  EXPECT_EQ(steps_to_reach(by_steps, 0.3), 42);
}

TEST(RunLength, RunEndsAtTheFirstStepPastTheTime) {
  test::TempDir dir;
  Scene s = test::jostling_pile(4, 3);
  s.simulation.backend = Backend::Cpu;
  s.simulation.steps = 0;
  s.simulation.duration = 2.5e-3;
  s.output.dir = dir.path().string();
  RunOptions o;
  o.progress = false;
  o.log = nullptr;
  const double dt = estimate_time_step(s, build_particle_model(s)).chosen;
  const RunSummary r = run_scene(s, o);
  EXPECT_GT(r.steps, 5);
  EXPECT_GE(static_cast<double>(r.steps) * dt, 2.5e-3);
  EXPECT_LT(static_cast<double>(r.steps - 1) * dt, 2.5e-3);
  SceneOverrides steps;  // --steps sets the length whichever key the scene used
  steps.steps = 3;
  EXPECT_EQ(run_scene(apply_overrides(s, steps), o).steps, 3);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
