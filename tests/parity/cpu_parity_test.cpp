// Every CPU way of computing a step against the serial reference: OpenMP must reproduce it
// bit for bit (same sums in the same order), all-pairs must find the same contacts as the
// cell grid (rounding apart: its pairs are summed in another order), and float must stay
// close over a short run.
#include "support/jostling_pile.hpp"
#include "support/scene_builder.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <omp.h>

namespace tridem {
namespace {

void expect_identical(const Snapshot& a, const Snapshot& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.x[i], b.x[i]) << "particle " << i;
    ASSERT_EQ(a.y[i], b.y[i]) << "particle " << i;
    ASSERT_EQ(a.theta[i], b.theta[i]) << "particle " << i;
    ASSERT_EQ(a.vx[i], b.vx[i]) << "particle " << i;
    ASSERT_EQ(a.omega[i], b.omega[i]) << "particle " << i;
    ASSERT_EQ(a.fx[i], b.fx[i]) << "particle " << i;
  }
  ASSERT_EQ(a.contacts.size(), b.contacts.size());
}

TEST(CpuParity, OpenMPReproducesSerialBitForBit) {
  const Scene s = test::jostling_pile(20, 12);
  const int saved = omp_get_max_threads();
  const Snapshot serial = test::run_to(s, Backend::Cpu, 400);
  for (int threads : {2, 3, 4}) {
    omp_set_num_threads(threads);
    const Snapshot parallel = test::run_to(s, Backend::OpenMP, 400);
    expect_identical(serial, parallel);
  }
  omp_set_num_threads(saved);
  EXPECT_GT(serial.contacts.size(), 30u) << "the pile must be in contact at the last step";
}

TEST(CpuParity, SerialRunIsDeterministic) {
  const Scene s = test::jostling_pile(10, 6);
  expect_identical(test::run_to(s, Backend::Cpu, 300), test::run_to(s, Backend::Cpu, 300));
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

TEST(CpuParity, FloatStaysCloseToDoubleOverShortRun) {
  const Scene s = test::jostling_pile(8, 5);
  const Snapshot d = test::run_to(s, Backend::Cpu, 50);
  const Snapshot f = test::run_to(s, Backend::Cpu, 50, Precision::Float);
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_NEAR(d.x[i], f.x[i], 1e-4) << "particle " << i;
    EXPECT_NEAR(d.y[i], f.y[i], 1e-4) << "particle " << i;
  }
}

}  // namespace
}  // namespace tridem
