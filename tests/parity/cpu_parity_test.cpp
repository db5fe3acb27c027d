// Every CPU way of computing a step against the serial reference: OpenMP must reproduce it
// bit for bit (same sums in the same order), all-pairs must find the same contacts as the
// cell grid (rounding apart: its pairs are summed in another order), and float must stay
// close over a short run.
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"

#include <gtest/gtest.h>
#include <omp.h>

namespace tridem {
namespace {

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
