// The time loop with a StepObserver (the live view's hook): it advances in its own chunks
// while the observer lets it, cuts them where the observer says, goes step by step when
// told to, and gives the observer the rate it measured.
#include "support/scene_builder.hpp"
#include "tridem/run.hpp"
#include "tridem/solver.hpp"
#include "tridem/step_observer.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// Lets the loop run at most `limit` steps between looks (0: as many as it likes) and
/// records what it saw.
class CountingObserver final : public StepObserver {
 public:
  explicit CountingObserver(std::int64_t limit) : limit_(limit) {}
  std::int64_t steps_before_look(std::int64_t steps, double seconds_per_step) override {
    EXPECT_GE(steps, 1);
    if (asked_ > 0) {
      EXPECT_GT(seconds_per_step, 0) << "after the first chunk";
    }
    ++asked_;
    return limit_ > 0 ? limit_ : steps;
  }
  void after_advance(const Solver& solver, const std::atomic<int>*) override {
    steps_seen.push_back(solver.step());
  }
  void run_ended(const Solver& solver) override { ended_at = solver.step(); }

  std::vector<std::int64_t> steps_seen;
  std::int64_t ended_at = -1;

 private:
  std::int64_t limit_;
  int asked_ = 0;
};

std::vector<std::int64_t> run_observed(CountingObserver& observer, std::int64_t steps) {
  test::TempDir dir;
  Scene s = test::jostling_pile(4, 3);
  s.simulation.backend = Backend::Cpu;
  s.simulation.steps = steps;
  s.output.dir = dir.path().string();
  s.output.every = 0;
  RunOptions o;
  o.progress = false;
  o.log = nullptr;
  o.observer = &observer;
  EXPECT_EQ(run_scene(s, o).steps, steps);
  EXPECT_EQ(observer.ended_at, steps);
  return observer.steps_seen;
}

TEST(ObservedLoop, KeepsItsChunksWhileTheObserverLetsIt) {
  CountingObserver observer(0);
  const std::vector<std::int64_t> seen = run_observed(observer, 3000);
  // Chunks double from one step while they are quick: far fewer looks than steps (a
  // watched run went step by step before issue 18's second part).
  EXPECT_LT(seen.size(), 300U);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), 3000);
}

TEST(ObservedLoop, CutsItsChunksWhereTheObserverSays) {
  CountingObserver observer(7);
  const std::vector<std::int64_t> seen = run_observed(observer, 200);
  std::int64_t before = 0;
  for (std::int64_t step : seen) {
    EXPECT_GE(step - before, 1);
    EXPECT_LE(step - before, 7) << "at step " << step;
    before = step;
  }
  EXPECT_EQ(before, 200);
  EXPECT_LT(seen.size(), 100U) << "chunks of up to 7 steps, not one";
}

TEST(ObservedLoop, GoesStepByStepWhenTold) {
  CountingObserver observer(1);
  const std::vector<std::int64_t> seen = run_observed(observer, 50);
  ASSERT_EQ(seen.size(), 50U);
  for (std::size_t k = 0; k < seen.size(); ++k)
    EXPECT_EQ(seen[k], static_cast<std::int64_t>(k + 1));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
