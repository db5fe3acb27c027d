// Every CPU way of computing a step against the serial reference: OpenMP must reproduce it
// bit for bit (same sums in the same order), all-pairs must find the same contacts as the
// cell grid (rounding apart: its pairs are summed in another order), and float must stay
// close over a short run.
#include "support/scene_builder.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <omp.h>
#include <random>

namespace tridem {
namespace {

/// A dense, jostling pile in a box: walls, gravity, friction, damping, random shapes.
Scene jostling_pile(int columns, int rows) {
  Scene s = test::empty_scene(1e7, 2000, 0.4, 0.2);
  s.simulation.gravity = {0, -9.81};
  const double pitch = 0.1, r = 0.055;
  const double width = columns * pitch;
  s.triangles.push_back(test::floor_triangle(-1, width + 1, -0.06));
  s.triangles.push_back(test::triangle({-0.06, -0.1}, {-0.06, rows * pitch}, {-1, 0},
                                       {}, Motion::Fixed));
  s.triangles.push_back(test::triangle({width, rows * pitch}, {width, -0.1}, {width + 1, 0},
                                       {}, Motion::Fixed));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const Vec2d c{i * pitch + 0.5 * pitch * (j % 2), j * pitch};
      const double a0 = 3.14159 * u(rng);
      TriangleSpec t;
      for (int k = 0; k < 3; ++k) {
        const double a = a0 + k * 2.0943951023931953 + 0.25 * u(rng);
        t.vertices[k] = {c.x + r * std::cos(a), c.y + r * std::sin(a)};
      }
      t.velocity = {2.0 * u(rng), 2.0 * u(rng)};
      s.triangles.push_back(t);
    }
  return s;
}

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
  const Scene s = jostling_pile(20, 12);
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
  const Scene s = jostling_pile(10, 6);
  expect_identical(test::run_to(s, Backend::Cpu, 300), test::run_to(s, Backend::Cpu, 300));
}

TEST(CpuParity, AllPairsAgreesWithCellGrid) {
  const Scene s = jostling_pile(12, 8);
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
  const Scene s = jostling_pile(8, 5);
  const Snapshot d = test::run_to(s, Backend::Cpu, 50);
  const Snapshot f = test::run_to(s, Backend::Cpu, 50, Precision::Float);
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_NEAR(d.x[i], f.x[i], 1e-4) << "particle " << i;
    EXPECT_NEAR(d.y[i], f.y[i], 1e-4) << "particle " << i;
  }
}

}  // namespace
}  // namespace tridem
