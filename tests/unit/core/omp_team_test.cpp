// One OpenMP team for a whole step (core/omp_team.hpp): team code called inside a team
// runs on that team (no region of its own) and shares its loops out, a team_single runs
// once (team_master on the first thread), an exception thrown there leaves every thread and
// is rethrown once by on_team, and a fold gives every thread the serial result.
#include "core/omp_team.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(OmpTeam, NestedTeamCodeRunsOnTheCallersTeamAndSharesItsLoops) {
  constexpr int n = 1000;
  std::vector<int> hits(n, 0), levels;
  std::atomic<int> calls{0};
  on_team(true, [&] {
    // The inner call makes no region of its own: the same team runs it, once per thread.
    on_team(true, [&] {
      ++calls;
#pragma omp for schedule(dynamic, 7)
      for (int i = 0; i < n; ++i) ++hits[i];
      team_single([&] { levels.push_back(omp_get_level()); });
    });
  });
  EXPECT_EQ(calls.load(), omp_get_max_threads());
  EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }))
      << "every iteration once, whatever the threads";
  ASSERT_EQ(levels.size(), 1u) << "a team_single runs once";
  EXPECT_EQ(levels[0], 1) << "one region, not a nested one";
}

// team_single (any one thread) and team_master (the first: MPI's calls) alike.
template <class Serial>
void expect_one_run_whose_exception_leaves_every_thread(Serial serial, bool first_thread) {
  std::atomic<int> runs{0}, left{0}, after{0};
  int ran_on = -1;
  try {
    on_team(true, [&] {
      try {
        serial([&] {
          ++runs;
          ran_on = omp_get_thread_num();
          throw std::runtime_error("blow-up");
        });
        ++after;  // never reached: every thread rethrows
      } catch (const std::runtime_error&) {
        ++left;
        throw;
      }
    });
    FAIL() << "on_team must rethrow the team's exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "blow-up");
  }
  EXPECT_EQ(runs.load(), 1);
  if (first_thread) {
    EXPECT_EQ(ran_on, 0) << "the thread that called on_team";
  }
  EXPECT_EQ(left.load(), omp_get_max_threads());
  EXPECT_EQ(after.load(), 0);
}

TEST(OmpTeam, ASingleRunsOnceAndItsExceptionLeavesEveryThread) {
  expect_one_run_whose_exception_leaves_every_thread([](auto&& f) { team_single(f); }, false);
}

TEST(OmpTeam, AMasterRunsOnTheFirstThreadAndItsExceptionLeavesEveryThread) {
  expect_one_run_whose_exception_leaves_every_thread([](auto&& f) { team_master(f); }, true);
}

TEST(OmpTeam, AFoldGivesEveryThreadTheSerialMinimum) {
  constexpr std::int64_t n = 10007, none = INT64_MAX;
  std::vector<std::int64_t> seen(static_cast<std::size_t>(omp_get_max_threads()), -1);
  std::int64_t shared = none;
  on_team(true, [&] {
    std::int64_t mine = none;
#pragma omp for schedule(static) nowait
    for (std::int64_t i = 0; i < n; ++i)
      if (i % 97 == 13) mine = std::min(mine, i);
    team_fold(shared, mine, [](std::int64_t a, std::int64_t b) { return std::min(a, b); });
    seen[static_cast<std::size_t>(omp_get_thread_num())] = shared;
  });
  for (const std::int64_t s : seen) EXPECT_EQ(s, 13);
}

TEST(OmpTeam, OutsideATeamItIsSerialCode) {
  std::vector<int> order;
  on_team(false, [&] {
    EXPECT_EQ(omp_get_num_threads(), 1);
#pragma omp for schedule(dynamic, 1)
    for (int i = 0; i < 5; ++i) order.push_back(i);
    team_single([&] { order.push_back(99); });
  });
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4, 99}));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
