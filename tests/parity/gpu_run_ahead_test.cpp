// Run-ahead (CudaSolver::advance_ahead, docs/performance.md "Run-ahead"): the CUDA solver
// launches each step before it has read the status of the one before it. That must change
// nothing but the speed: the bits of a solver that waits for every step
// (SolverConfig::gpu_run_ahead = false), in both precisions, over advance() calls of any
// length, with and without the stage clock (whose sampled steps run staged); steps held back
// by a list build and launched again; and a blow-up on a step launched ahead reported with
// the same message at the same step, the state left the last good one.
#include "support/gpu.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"
#include "tridem/solver.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

struct Outcome {
  Snapshot snapshot;
  EnergyBudget energy;
  std::string statistics;
  std::string error;  ///< the RunError's message, if a step blew up
  std::int64_t step = 0;
};

Outcome run(Scene s, Backend backend, Precision precision, bool ahead,
            const std::vector<std::int64_t>& advances, bool timing = true) {
  s.simulation.backend = backend;
  s.simulation.precision = precision;
  SolverConfig config;
  config.gpu_run_ahead = ahead;
  const auto solver = make_solver(s, config);
  solver->set_stage_timing(timing);
  Outcome r;
  try {
    for (const std::int64_t k : advances) solver->advance(k);
  } catch (const RunError& e) {
    r.error = e.what();
  }
  r.step = solver->step();
  solver->snapshot(r.snapshot, true);
  r.energy = solver->energy();
  r.statistics = solver->statistics();
  return r;
}

void expect_same_run(const Outcome& waiting, const Outcome& ahead) {
  EXPECT_EQ(waiting.error, ahead.error);
  EXPECT_EQ(waiting.step, ahead.step);
  test::expect_identical(waiting.snapshot, ahead.snapshot);
  EXPECT_TRUE(test::same_bits(waiting.energy.elastic, ahead.energy.elastic));
  EXPECT_TRUE(test::same_bits(waiting.energy.dissipated_local, ahead.energy.dissipated_local));
  EXPECT_TRUE(
      test::same_bits(waiting.energy.dissipated_friction, ahead.energy.dissipated_friction));
  EXPECT_TRUE(test::same_bits(waiting.energy.dissipated_damping, ahead.energy.dissipated_damping));
  EXPECT_TRUE(test::same_bits(waiting.energy.wall_work, ahead.energy.wall_work));
}

/// The run-ahead counts of CudaSolver::statistics(): steps launched ahead, and of them the
/// ones held back and launched again; {-1, -1} when it says nothing of run-ahead.
std::pair<long long, long long> ahead_counts(const std::string& statistics) {
  const std::size_t at = statistics.find("; ", statistics.find("room for"));
  long long launched = -1, again = -1;
  if (at != std::string::npos &&
      std::sscanf(statistics.c_str() + at,
                  "; %lld steps launched ahead of the last one's check (%lld launched again",
                  &launched, &again) == 2)
    return {launched, again};
  return {-1, -1};
}

// 400 steps of a jostling pile whose list is built again as it settles, in advances of
// 1 to 200 steps (a step is launched ahead only within one advance).
const std::vector<std::int64_t> kAdvances = {1, 2, 3, 50, 144, 200};

void expect_run_ahead_is_exact(Precision precision, bool timing) {
  const Scene s = test::jostling_pile(20, 12);
  const Outcome waiting = run(s, Backend::Cuda, precision, false, kAdvances, timing);
  const Outcome ahead = run(s, Backend::Cuda, precision, true, kAdvances, timing);
  expect_same_run(waiting, ahead);
  EXPECT_GT(ahead.snapshot.contacts.size(), 10u) << "the scene's grains touch";
  EXPECT_EQ(ahead_counts(waiting.statistics).first, -1) << waiting.statistics;
  const auto [launched, again] = ahead_counts(ahead.statistics);
  // Every step but the first of each advance, less the steps the clock samples (1 in 16).
  EXPECT_GT(launched, timing ? 300 : 390) << ahead.statistics;
  EXPECT_LE(launched, 400 - static_cast<long long>(kAdvances.size())) << ahead.statistics;
  EXPECT_GE(again, 1) << "a list build held a launched step back: " << ahead.statistics;
  // The same list builds, at the same steps: the statistics' first part is the same.
  EXPECT_EQ(waiting.statistics, ahead.statistics.substr(0, waiting.statistics.size()));
}

TEST(GpuRunAhead, GivesTheBitsOfWaitingForEachStepInDouble) {
  TRIDEM_SKIP_WITHOUT_GPU();
  expect_run_ahead_is_exact(Precision::Double, true);
  expect_run_ahead_is_exact(Precision::Double, false);
}

TEST(GpuRunAhead, GivesTheBitsOfWaitingForEachStepInFloat) {
  TRIDEM_SKIP_WITHOUT_GPU();
  expect_run_ahead_is_exact(Precision::Float, true);
  expect_run_ahead_is_exact(Precision::Float, false);
}

/// A small pile and a grain shot into it: a step some way into the run overlaps too deep.
Scene shot_into_pile() {
  Scene s = test::jostling_pile(6, 4);
  s.simulation.max_penetration = 0.3;
  s.triangles.push_back(test::triangle({0.27, 0.55}, {0.33, 0.55}, {0.30, 0.50}, {0, -200}));
  return s;
}

// The CPU stops the run some steps in (step 42); the GPU, running ahead, where the GPU
// waiting for every step does, with the same words and the same last good state.
TEST(RunAheadBlowUp, TheShotPileBlowsUpSomeStepsIn) {
  const Outcome cpu = run(shot_into_pile(), Backend::Cpu, Precision::Double, true, {400});
  EXPECT_NE(cpu.error.find("blow-up at step"), std::string::npos) << cpu.error;
  EXPECT_GT(cpu.step, 2) << "the blow-up is on a step launched ahead on the GPU";
  EXPECT_LT(cpu.step, 400);
}

TEST(GpuRunAhead, ABlowUpOnAStepLaunchedAheadIsTheWaitingOne) {
  TRIDEM_SKIP_WITHOUT_GPU();
  for (const Precision precision : {Precision::Double, Precision::Float}) {
    SCOPED_TRACE(std::string(precision_name(precision)));
    const Outcome waiting = run(shot_into_pile(), Backend::Cuda, precision, false, {400});
    const Outcome ahead = run(shot_into_pile(), Backend::Cuda, precision, true, {400});
    EXPECT_NE(waiting.error, "");
    EXPECT_GT(waiting.step, 2);
    expect_same_run(waiting, ahead);
  }
}

// Scenes whose steps read what the host decides between them wait for every step.
TEST(GpuRunAhead, ScenesThatNeedTheHostBetweenStepsWaitForEachStep) {
  TRIDEM_SKIP_WITHOUT_GPU();
  Scene s = test::jostling_pile(6, 4);
  s.simulation.method = Method::SingleDomain;
  EXPECT_EQ(ahead_counts(run(s, Backend::Cuda, Precision::Double, true, {20}).statistics).first,
            -1);
  EXPECT_GT(
      ahead_counts(
          run(test::jostling_pile(6, 4), Backend::Cuda, Precision::Double, true, {20}).statistics)
          .first,
      0);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
