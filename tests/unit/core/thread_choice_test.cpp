// The openmp backend's choice between its threads and one thread (backends/cpu/
// thread_choice.hpp), on step times given by the test: it must leave threads that lose to
// one thread, come back when they win again, cost little where threads pay, need a clear
// margin, and never choose for a serial solver or a pinned one.
#include "backends/cpu/thread_choice.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// Runs `steps` steps with the given seconds per step on the threads and on one; returns the
// seconds they took.
double run(ThreadChoice& c, int steps, double threads_s, double one_s) {
  double total = 0;
  for (int s = 0; s < steps; ++s) {
    const double t = c.parallel() ? threads_s : one_s;
    c.record(t);
    total += t;
  }
  return total;
}

TEST(ThreadChoice, LeavesThreadsThatAreSlowerThanOne) {
  ThreadChoice c(true, ThreadUse::Measured);
  EXPECT_TRUE(c.parallel()) << "an openmp solver starts on its threads";
  run(c, 100, 10e-3, 1e-3);  // busy cores: a barrier waits for a descheduled thread
  EXPECT_FALSE(c.parallel());
  EXPECT_EQ(c.switches(), 1);
  // Later trials of the threads cost about 2% of the time.
  const double spent = run(c, 20'000, 10e-3, 1e-3);
  EXPECT_FALSE(c.parallel());
  EXPECT_EQ(c.switches(), 1);
  EXPECT_LT(spent, 1.03 * 20'000 * 1e-3);
}

TEST(ThreadChoice, ComesBackToThreadsWhenTheyWinAgain) {
  ThreadChoice c(true, ThreadUse::Measured);
  run(c, 100, 10e-3, 1e-3);
  ASSERT_FALSE(c.parallel());
  run(c, 40'000, 0.4e-3, 1e-3);  // the other programs ended
  EXPECT_TRUE(c.parallel());
  EXPECT_EQ(c.switches(), 2);
}

TEST(ThreadChoice, KeepsThreadsThatPay) {
  ThreadChoice c(true, ThreadUse::Measured);
  const double spent = run(c, 20'000, 1e-3, 16e-3);  // 16 idle cores
  EXPECT_TRUE(c.parallel());
  EXPECT_EQ(c.switches(), 0);
  EXPECT_LT(spent, 1.03 * 20'000 * 1e-3);
  EXPECT_GT(c.steps() - c.parallel_steps(), 0) << "one thread was tried";
}

TEST(ThreadChoice, TrialsOfSlowStepsStayAFewPercent) {
  // 10^6 triangles: a serial step of seconds against a quarter second on the threads.
  ThreadChoice c(true, ThreadUse::Measured);
  const double spent = run(c, 2'000, 0.28, 3.7);
  EXPECT_TRUE(c.parallel());
  EXPECT_LT(spent, 1.05 * 2'000 * 0.28);
}

TEST(ThreadChoice, NeedsAClearMarginToSwitch) {
  ThreadChoice c(true, ThreadUse::Measured);
  run(c, 20'000, 1.0e-3, 0.95e-3);  // within the 10% margin: noise, not a reason
  EXPECT_TRUE(c.parallel());
  EXPECT_EQ(c.switches(), 0);
}

TEST(ThreadChoice, SerialAndPinnedSolversNeverChoose) {
  ThreadChoice serial(false, ThreadUse::Measured);
  run(serial, 500, 1e-3, 1e-3);
  EXPECT_EQ(serial.parallel_steps(), 0);
  ThreadChoice pinned(true, ThreadUse::Always);
  run(pinned, 500, 10e-3, 1e-3);
  EXPECT_EQ(pinned.parallel_steps(), 500);
  ThreadChoice alternating(true, ThreadUse::Alternating);
  run(alternating, 500, 10e-3, 1e-3);
  EXPECT_EQ(alternating.parallel_steps(), 250);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
