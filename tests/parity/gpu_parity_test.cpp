// The CUDA solver against the serial reference (the tolerances and why: support/gpu_compare.hpp).
#include "support/gpu.hpp"
#include "support/float_compare.hpp"
#include "support/gpu_compare.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_agreement;

TEST(GpuParity, DoubleAgreesWithSerialOnJostlingPiles) {
  TRIDEM_SKIP_WITHOUT_GPU();
  for (unsigned seed : {5u, 6u, 7u}) {
    const Scene s = test::jostling_pile(20, 12, seed);
    const Snapshot cpu = test::run_to(s, Backend::Cpu, 200);
    const Snapshot gpu = test::run_to(s, Backend::Cuda, 200);
    EXPECT_GT(cpu.contacts.size(), 20u) << "the pile must be in contact";
    expect_agreement(cpu, gpu, ("jostling pile, seed " + std::to_string(seed)).c_str());
  }
}

TEST(GpuParity, AllPairsAgreesWithSerial) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s = test::jostling_pile(12, 8);
  expect_agreement(test::run_to(s, Backend::Cpu, 200, Precision::Double, Method::AllPairs),
                   test::run_to(s, Backend::Cuda, 200, Precision::Double, Method::AllPairs),
                   "all-pairs");
}

/// The pile run with the single-domain method and the given contact test and pre-filter.
Snapshot single_domain(Scene s, Backend backend, std::int64_t steps, ContactTest test,
                       bool prefilter = true) {
  s.simulation.contact_test = test;
  s.simulation.bbox_prefilter = prefilter;
  return test::run_to(s, backend, steps, Precision::Double, Method::SingleDomain);
}

// The paper's kernel (blocks of 64, tiles in shared memory) against the CPU's
// single-domain detection: the same rows, so the same agreement as the grid's.
TEST(GpuParity, SingleDomainAgreesWithSerial) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s = test::jostling_pile(20, 12);  // 243 particles: the last tile is partial
  for (ContactTest t : {ContactTest::Exact, ContactTest::DirectArea}) {
    const std::string what = std::string("single-domain, ") + (t == ContactTest::Exact ? "exact" : "direct-area");
    expect_agreement(single_domain(s, Backend::Cpu, 200, t), single_domain(s, Backend::Cuda, 200, t),
                     what.c_str());
  }
}

// As on the CPU: with the exact test the list lacks only pairs that add exact zeros, so
// the GPU's grid (with its skin) and single-domain agree bit for bit; the pre-filter
// changes nothing either.
TEST(GpuParity, SingleDomainExactReproducesCudaGridBitForBit) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s = test::jostling_pile(20, 12);
  const Snapshot grid = test::run_to(s, Backend::Cuda, 300);
  for (bool prefilter : {true, false}) {
    SCOPED_TRACE(prefilter ? "bbox pre-filter on" : "bbox pre-filter off");
    test::expect_identical(grid, single_domain(s, Backend::Cuda, 300, ContactTest::Exact, prefilter));
  }
  test::expect_identical(single_domain(s, Backend::Cuda, 300, ContactTest::DirectArea, true),
                         single_domain(s, Backend::Cuda, 300, ContactTest::DirectArea, false));
}

TEST(GpuParity, TwoRunsAreBitIdentical) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s = test::jostling_pile(20, 12);
  for (Precision p : {Precision::Double, Precision::Float})
    test::expect_identical(test::run_to(s, Backend::Cuda, 300, p), test::run_to(s, Backend::Cuda, 300, p));
}

// Pairs kept in the list by the skin but not touching add exact zeros, and the touching
// ones keep their order: any skin gives the same bits as rebuilding every step.
TEST(GpuParity, SkinDoesNotChangeTheResult) {
  TRIDEM_SKIP_WITHOUT_GPU();
  Scene rebuild_every_step = test::jostling_pile(20, 12);
  rebuild_every_step.simulation.skin = 0;
  Scene wide = rebuild_every_step;
  wide.simulation.skin = 0.3;
  test::expect_identical(test::run_to(rebuild_every_step, Backend::Cuda, 300),
                   test::run_to(wide, Backend::Cuda, 300));
}

TEST(GpuParity, FloatStaysCloseToSerialDouble) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s = test::jostling_pile(8, 5);
  test::expect_float_follows_double(s, 50, test::run_to(s, Backend::Cuda, 50, Precision::Float));
}

TEST(GpuParity, BlowUpKeepsTheLastGoodState) {
  TRIDEM_SKIP_WITHOUT_GPU();
  Scene s = test::empty_scene(1e9);
  s.simulation.dt = 1e-2;
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  s.triangles.push_back(test::triangle({0.2, 0.2}, {1.2, 0.2}, {0.2, 1.2}));
  s.simulation.backend = Backend::Cuda;
  SolverConfig config;
  config.force = true;
  auto solver = make_solver(s, config);
  Snapshot before;
  solver->snapshot(before, false);
  try {
    solver->advance(10);
    FAIL() << "the overlapping pair must blow up";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("blow-up at step 1: particle"), std::string::npos)
        << e.what();
  }
  Snapshot after;
  solver->snapshot(after, false);
  EXPECT_EQ(after.step, 0);
  EXPECT_EQ(before.x, after.x);
  EXPECT_EQ(before.vx, after.vx);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
