// The pipeline as code: every backend runs its stages through run_step and reports the
// time of each (Solver::stage_times), counting completed steps only; `tridem run` prints
// them as a table.
#include "core/stage_pipeline.hpp"
#include "core/stage_report.hpp"
#include "support/gpu.hpp"
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"
#include "tridem/solver.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <thread>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

std::unique_ptr<Solver> pile_solver(Backend backend) {
  Scene s = test::jostling_pile(4, 3);
  s.simulation.backend = backend;
  return make_solver(s, SolverConfig{});
}

void expect_every_stage_timed(Backend backend) {
  auto solver = pile_solver(backend);
  const auto start = std::chrono::steady_clock::now();
  solver->advance(20);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const StageTimes t = solver->stage_times();
  EXPECT_EQ(t.steps, 20);
  for (int k = 0; k < kStageCount; ++k) {
    if (t.fused_into[k] != k) {
      EXPECT_EQ(t.seconds[k], 0) << stage_name(static_cast<Stage>(k));
      continue;
    }
    EXPECT_GT(t.seconds[k], 0) << stage_name(static_cast<Stage>(k));
  }
  EXPECT_LE(t.total(), wall);
}

TEST(StageTimes, CpuTimesEveryStageOfEveryStep) {
  expect_every_stage_timed(Backend::Cpu);
  expect_every_stage_timed(Backend::OpenMP);
}

TEST(GpuStageTimes, TimesEveryStageItDoesNotFuse) {
  TRIDEM_SKIP_WITHOUT_GPU();
  expect_every_stage_timed(Backend::Cuda);
  const StageTimes t = pile_solver(Backend::Cuda)->stage_times();
  EXPECT_EQ(t.fused_into[static_cast<int>(Stage::Geometry)], static_cast<int>(Stage::Integrate));
}

TEST(StageTimes, OffTakesNoTimes) {
  auto solver = pile_solver(Backend::Cpu);
  solver->set_stage_timing(false);
  solver->advance(5);
  EXPECT_EQ(solver->stage_times().steps, 0);
  EXPECT_EQ(solver->stage_times().total(), 0);
  solver->set_stage_timing(true);
  solver->advance(3);
  EXPECT_EQ(solver->stage_times().steps, 3);
}

TEST(StageTimes, AStepStoppedByABlowUpIsNotCounted) {
  Scene s = test::empty_scene(1e3);
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  s.triangles.push_back(test::triangle({0.3, 0.3}, {1.3, 0.3}, {0.3, 1.3}));
  s.simulation.backend = Backend::Cpu;
  auto solver = make_solver(s, SolverConfig{});
  EXPECT_THROW(solver->advance(1), RunError);
  const StageTimes t = solver->stage_times();
  EXPECT_EQ(t.steps, 0);
  EXPECT_EQ(t.total(), 0);
}

/// A backend whose stages each take at least a millisecond, to see what a sampling clock
/// counts.
struct SleepyBackend {
  int runs = 0;
  void run_stage(Stage) {
    ++runs;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
};

TEST(StageTimes, ASampledClockTimesOneStepInEveryAndScalesToAllSteps) {
  constexpr std::array<Stage, 2> pipeline = {Stage::PairForces, Stage::Integrate};
  SleepyBackend backend;
  StageStopwatch clock;
  clock.every = 4;
  for (int s = 0; s < 10; ++s) run_step(backend, pipeline, clock);
  EXPECT_EQ(backend.runs, 20);  // untimed steps still run every stage
  const StageTimes t = clock.times();
  EXPECT_EQ(t.steps, 10);
  // Steps 3 and 7 (the middle of each window of four; the first step, with a solver's
  // one-off costs, is not a sample).
  EXPECT_EQ(t.timed_steps, 2);
  // Scaled to all ten steps: at least 10 ms per stage, not the 2 ms actually timed.
  EXPECT_GE(t.seconds[static_cast<int>(Stage::PairForces)], 10e-3);
  EXPECT_GE(t.seconds[static_cast<int>(Stage::Integrate)], 10e-3);
  EXPECT_NE(stage_table(t).find("10 steps, 2 of them timed"), std::string::npos) << stage_table(t);
}

/// A backend whose first step is slow (a solver's first pair-list build) and the others
/// quick.
struct SlowFirstStepBackend {
  int runs = 0;
  void run_stage(Stage) {
    std::this_thread::sleep_for(std::chrono::milliseconds(runs++ == 0 ? 40 : 1));
  }
};

// Scaled from a steady step, the stages stay below the run's wall time (they summed to
// four times it on the GPU when the first step was the sample).
TEST(StageTimes, ASampledClockDoesNotScaleTheFirstStepsOneOffCost) {
  constexpr std::array<Stage, 1> pipeline = {Stage::PairForces};
  SlowFirstStepBackend backend;
  StageStopwatch clock;
  clock.every = 16;
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < 20; ++s) run_step(backend, pipeline, clock);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const StageTimes t = clock.times();
  EXPECT_EQ(t.timed_steps, 1);
  EXPECT_LE(t.total(), wall);
  EXPECT_LT(t.total(), 0.2) << "20 x the 40 ms first step would be 0.8 s";
}

/// A clock whose readings slow the steps it samples, as CUDA's event records slow a
/// launch-bound step: 2 ms inside every timed stage.
struct IntrusiveStopwatch : StageStopwatch {
  void end_stage(Stage stage) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    StageStopwatch::end_stage(stage);
  }
};

/// Stages of 1 ms (pair forces) and 3 ms (integrate).
struct UnevenBackend {
  void run_stage(Stage stage) {
    std::this_thread::sleep_for(std::chrono::milliseconds(stage == Stage::PairForces ? 1 : 3));
  }
};

// Scaled by the step count, the two slowed samples of eight steps would sum to about 64 ms
// against 40 ms of steps; as shares of the steps' wall time they sum to no more than the
// run took, and the slower stage keeps the larger share.
TEST(StageTimes, SharesOfWallSumToTheStepsTimeWhenSamplingSlowsTheSamples) {
  constexpr std::array<Stage, 2> pipeline = {Stage::PairForces, Stage::Integrate};
  UnevenBackend backend;
  IntrusiveStopwatch clock;
  clock.every = 4;
  clock.shares_of_wall = true;
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < 8; ++s) run_step(backend, pipeline, clock);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const StageTimes t = clock.times();
  EXPECT_EQ(t.timed_steps, 2);
  EXPECT_LE(t.total(), wall);
  EXPECT_GE(t.total(), 8 * 4e-3);  // at least what the stages slept
  EXPECT_GT(t.seconds[static_cast<int>(Stage::Integrate)],
            t.seconds[static_cast<int>(Stage::PairForces)]);
  // The same clock scaled by the step count overstates the run: what the fix is for.
  IntrusiveStopwatch counting;
  counting.every = 4;
  for (int s = 0; s < 8; ++s) run_step(backend, pipeline, counting);
  EXPECT_GT(counting.times().total(), t.total() * 1.2);
}

// A run shorter than the first sample has no stage times, and its table says so rather
// than showing zeros.
TEST(StageTimes, TableOfARunWithNoTimedStepSaysSo) {
  SleepyBackend backend;
  StageStopwatch clock;
  clock.every = 16;
  constexpr std::array<Stage, 1> pipeline = {Stage::PairForces};
  for (int s = 0; s < 3; ++s) run_step(backend, pipeline, clock);
  const StageTimes t = clock.times();
  EXPECT_EQ(t.steps, 3);
  EXPECT_EQ(t.timed_steps, 0);
  EXPECT_NE(stage_table(t).find("none of the 3 steps was timed"), std::string::npos)
      << stage_table(t);
}

TEST(StageTimes, TableNamesEveryStageAndWhereFusedOnesWent) {
  StageTimes t;
  t.steps = 10;
  t.timed_steps = 10;  // as a clock fills it: every step timed
  t.clock = "test clock";
  for (int k = 0; k < kStageCount; ++k) t.seconds[k] = 0.5;
  t.seconds[static_cast<int>(Stage::Geometry)] = 0;
  t.fused_into[static_cast<int>(Stage::Geometry)] = static_cast<int>(Stage::Integrate);
  const std::string table = stage_table(t);
  EXPECT_NE(table.find("10 steps, test clock"), std::string::npos) << table;
  EXPECT_NE(table.find("geometry     in integrate"), std::string::npos) << table;
  EXPECT_NE(table.find("pair forces         0.5 s  20.0 %       0.05 s/step"), std::string::npos)
      << table;
  EXPECT_EQ(stage_table(StageTimes{}), "");
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
