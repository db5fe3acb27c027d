// The CUDA solver against the serial reference. Both run the same physics functions and
// sum every particle's pair forces in the same order, so in double precision they differ
// only by the device's own rounding: its sin and cos (within 2 ulp of glibc's) and fused
// multiply-adds. Those differences, about 1e-16 relative per operation, grow through the
// contacts of a dense pile; over 200 steps they stay many orders of magnitude below the
// tolerances used here (positions to 1e-9 m for 0.1 m grains, i.e. 1e-8 of a grain, and
// velocities to 1e-7 m/s for speeds of order 1 m/s), which a single missing or wrongly
// signed pair force exceeds by far. The measured differences are printed.
#include "support/gpu.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace tridem {
namespace {

constexpr double kPositionTolerance = 1e-9;  // m
constexpr double kAngleTolerance = 1e-8;     // rad
constexpr double kVelocityTolerance = 1e-7;  // m/s and rad/s × 0.1 m

struct Difference {
  double position = 0, angle = 0, velocity = 0;
};

Difference max_difference(const Snapshot& a, const Snapshot& b) {
  Difference d;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d.position = std::max({d.position, std::abs(a.x[i] - b.x[i]), std::abs(a.y[i] - b.y[i])});
    d.angle = std::max(d.angle, std::abs(a.theta[i] - b.theta[i]));
    d.velocity = std::max({d.velocity, std::abs(a.vx[i] - b.vx[i]), std::abs(a.vy[i] - b.vy[i]),
                           0.1 * std::abs(a.omega[i] - b.omega[i])});
  }
  return d;
}

void expect_agreement(const Snapshot& cpu, const Snapshot& gpu, const char* what) {
  ASSERT_EQ(cpu.size(), gpu.size());
  ASSERT_EQ(cpu.step, gpu.step);
  const Difference d = max_difference(cpu, gpu);
  std::printf("%s: max |dx| %.3g m, |dtheta| %.3g rad, |dv| %.3g m/s, contacts %zu/%zu\n", what,
              d.position, d.angle, d.velocity, cpu.contacts.size(), gpu.contacts.size());
  EXPECT_LE(d.position, kPositionTolerance) << what;
  EXPECT_LE(d.angle, kAngleTolerance) << what;
  EXPECT_LE(d.velocity, kVelocityTolerance) << what;
  EXPECT_EQ(cpu.contacts.size(), gpu.contacts.size()) << what;
  // Forces on the walls too: they are summed on the GPU only for output.
  for (std::size_t i = 0; i < cpu.size(); ++i)
    if (cpu.motion[i] != Motion::Free) {
      const double scale = 1e-6 * (1 + std::hypot(cpu.fx[i], cpu.fy[i]));
      EXPECT_NEAR(cpu.fx[i], gpu.fx[i], scale) << what << ": wall " << i;
      EXPECT_NEAR(cpu.fy[i], gpu.fy[i], scale) << what << ": wall " << i;
    }
}

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
  const Snapshot d = test::run_to(s, Backend::Cpu, 50);
  const Snapshot f = test::run_to(s, Backend::Cuda, 50, Precision::Float);
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_NEAR(d.x[i], f.x[i], 1e-4) << "particle " << i;
    EXPECT_NEAR(d.y[i], f.y[i], 1e-4) << "particle " << i;
  }
}

TEST(GpuParity, BlowUpKeepsTheLastGoodState) {
  TRIDEM_SKIP_WITHOUT_GPU();
  Scene s = test::empty_scene(1e9);
  s.simulation.dt = 1e-2;
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  s.triangles.push_back(test::triangle({0.2, 0.2}, {1.2, 0.2}, {0.2, 1.2}));
  SolverConfig config;
  config.backend = Backend::Cuda;
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

}  // namespace
}  // namespace tridem
