// Every CPU way of computing a step against the serial reference: OpenMP must reproduce it
// bit for bit (same sums in the same order), all-pairs must find the same contacts as the
// cell grid (rounding apart: its pairs are summed in another order), single-domain with
// the exact test must reproduce the grid bit for bit, and float must stay close over a
// short run.
#include "support/float_compare.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(CpuParity, OpenMPReproducesSerialBitForBit) {
  const Scene s = test::jostling_pile(20, 12);
  const int saved = omp_get_max_threads();
  const Snapshot serial = test::run_to(s, Backend::Cpu, 400);
  for (int threads : {2, 3, 4}) {
    omp_set_num_threads(threads);
    const Snapshot parallel = test::run_to(s, Backend::OpenMP, 400);
    test::expect_identical(serial, parallel);
  }
  omp_set_num_threads(saved);
  EXPECT_GT(serial.contacts.size(), 30u) << "the pile must be in contact at the last step";
}

// tridem run lets the openmp backend switch between its threads and one thread at any step
// (backends/cpu/thread_choice.hpp): both ways must give the same bits, step after step.
TEST(CpuParity, SwitchingBetweenThreadsAndOneThreadEachStepReproducesSerial) {
  const Scene s = test::jostling_pile(20, 12);
  const Snapshot serial = test::run_to(s, Backend::Cpu, 301);
  Scene omp = s;
  omp.simulation.backend = Backend::OpenMP;
  SolverConfig config;
  config.threads = 2;
  config.thread_use = ThreadUse::Alternating;
  auto solver = make_solver(omp, config);
  solver->advance(301);
  Snapshot switching;
  solver->snapshot(switching, true);
  test::expect_identical(serial, switching);
  EXPECT_NE(solver->statistics().find("150 of 301 steps on one thread"), std::string::npos)
      << solver->statistics();
}

// --threads is the solver's own: a program that makes a solver with N threads keeps its
// own OpenMP setting (it was once set globally from the constructor).
TEST(CpuParity, SolverThreadsLeaveTheCallersSettingAlone) {
  const int before = omp_get_max_threads();
  const int threads = before + 1;
  Scene s = test::jostling_pile(10, 6);
  s.simulation.backend = Backend::OpenMP;
  SolverConfig config;
  config.threads = threads;
  auto solver = make_solver(s, config);
  EXPECT_EQ(omp_get_max_threads(), before) << "after construction";
  solver->advance(50);
  EXPECT_EQ(omp_get_max_threads(), before) << "after advance";
  EXPECT_NE(solver->description().find(fmt::format("({} threads)", threads)), std::string::npos)
      << solver->description();
  Snapshot parallel;
  solver->snapshot(parallel, true);
  test::expect_identical(test::run_to(s, Backend::Cpu, 50), parallel);
}

TEST(CpuParity, SerialRunIsDeterministic) {
  const Scene s = test::jostling_pile(10, 6);
  test::expect_identical(test::run_to(s, Backend::Cpu, 300), test::run_to(s, Backend::Cpu, 300));
}

TEST(CpuParity, AllPairsAgreesWithCellGrid) {
  const Scene s = test::jostling_pile(12, 8);
  const std::int64_t steps = 200;
  const Snapshot grid = test::run_to(s, Backend::Cpu, steps);
  const Snapshot all = test::run_to(s, Backend::Cpu, steps, Precision::Double, Method::AllPairs);
  ASSERT_EQ(grid.size(), all.size());
  ASSERT_EQ(grid.contacts.size(), all.contacts.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_NEAR(grid.x[i], all.x[i], 1e-9) << "particle " << i;
    EXPECT_NEAR(grid.y[i], all.y[i], 1e-9) << "particle " << i;
    EXPECT_NEAR(grid.theta[i], all.theta[i], 1e-7) << "particle " << i;
  }
}

/// The pile run to `steps` with the single-domain method and the given settings.
Snapshot single_domain(Scene s, Backend backend, std::int64_t steps, ContactTest test,
                       bool prefilter) {
  s.simulation.contact_test = test;
  s.simulation.bbox_prefilter = prefilter;
  return test::run_to(s, backend, steps, Precision::Double, Method::SingleDomain);
}

// With the exact test, single-domain drops only pairs whose force pair_force would find
// zero by the same separating-axis arithmetic (and whose slip it would reset, as a pair
// absent from the list gets), in rows the grid's emitter rule orders the same way: the
// same sums in the same order, so the grid's results bit for bit. (The two tests are one
// expression, cross(d, q - p); a compiler that contracted it to a fused multiply-add in
// one place and not the other could flip a pair that touches to within rounding.)
TEST(CpuParity, SingleDomainExactReproducesGridBitForBit) {
  const Scene s = test::jostling_pile(12, 8);
  const Snapshot grid = test::run_to(s, Backend::Cpu, 300);
  for (bool prefilter : {true, false}) {
    SCOPED_TRACE(prefilter ? "bbox pre-filter on" : "bbox pre-filter off");
    test::expect_identical(grid, single_domain(s, Backend::Cpu, 300, ContactTest::Exact, prefilter));
  }
  EXPECT_GT(grid.contacts.size(), 20u) << "the pile must be in contact at the last step";
}

TEST(CpuParity, SingleDomainOpenMPReproducesSerialBitForBit) {
  const Scene s = test::jostling_pile(10, 6);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(3);
  for (ContactTest t : {ContactTest::Exact, ContactTest::DirectArea})
    test::expect_identical(single_domain(s, Backend::Cpu, 200, t, true),
                           single_domain(s, Backend::OpenMP, 200, t, true));
  omp_set_num_threads(saved);
}

// The pre-filter only skips pairs whose boxes are apart, which neither test passes.
TEST(CpuParity, BboxPrefilterChangesNoResult) {
  const Scene s = test::jostling_pile(10, 6);
  test::expect_identical(single_domain(s, Backend::Cpu, 200, ContactTest::DirectArea, true),
                         single_domain(s, Backend::Cpu, 200, ContactTest::DirectArea, false));
}

// Mixed precision far from the origin: a pile of 1 mm grains at (10 km, 10 km), where a
// float coordinate is resolved to 1 mm, so the float boxes (rounded outward) are two to
// three grains wide. The grid must still list every touching pair (its cell grows to the
// widest box: LocalFrame.GridFindsOverlappingBoxesWiderThanItsBaseCell checks that rule
// on a case built for it). Single-domain with the exact test and no pre-filter tests every
// pair in the pair's own frame, so any pair the grid missed would change the result.
TEST(CpuParity, FloatGridFindsEveryContactFarFromOrigin) {
  Scene s = test::jostling_pile(12, 8);
  for (TriangleSpec& t : s.triangles)
    for (Vec2d& v : t.vertices) v = v * 0.01 + Vec2d{1e4, 1e4};
  const Snapshot grid = test::run_to(s, Backend::Cpu, 600, Precision::Float);
  s.simulation.bbox_prefilter = false;
  test::expect_identical(
      grid, test::run_to(s, Backend::Cpu, 600, Precision::Float, Method::SingleDomain));
  EXPECT_GT(grid.contacts.size(), 10u) << "the pile must be in contact at the last step";
}

TEST(CpuParity, FloatStaysCloseToDoubleOverShortRun) {
  const Scene s = test::jostling_pile(8, 5);
  test::expect_float_follows_double(s, 50, test::run_to(s, Backend::Cpu, 50, Precision::Float));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
