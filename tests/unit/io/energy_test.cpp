#include "tridem/output.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

Snapshot particles(std::size_t n) {
  Snapshot s;
  s.resize(n);
  return s;
}

void set(Snapshot& s, std::size_t k, double m, double inertia, double x, double y, double vx,
         double vy, double w, Motion motion) {
  s.mass[k] = m, s.inertia[k] = inertia, s.x[k] = x, s.y[k] = y;
  s.vx[k] = vx, s.vy[k] = vy, s.omega[k] = w, s.motion[k] = motion;
}

TEST(ComputeEnergy, HandComputedFreeParticlesOnly) {
  Snapshot s = particles(4);
  s.step = 7;
  s.time = 0.5;
  // KE = ½·2·10 + ½·0.5·16 = 14;  p = (6, −2);  L = 2·(1·(−1) − 2·3) + 0.5·4 = −12
  set(s, 0, 2, 0.5, 1, 2, 3, -1, 4, Motion::Free);
  // KE = ½·1·4 + ½·0.25·4 = 2.5;  p = (0, 2);  L = 1·(−1·2 − 0.5·0) + 0.25·(−2) = −2.5
  set(s, 1, 1, 0.25, -1, 0.5, 0, 2, -2, Motion::Free);
  // Imposed motion: must not count.
  set(s, 2, 100, 10, 3, 3, 5, 5, 1, Motion::Fixed);
  set(s, 3, 50, 7, -2, 1, -4, 0, 2, Motion::Prescribed);

  const EnergyRow e = compute_energy(s);
  EXPECT_EQ(e.step, 7);
  EXPECT_DOUBLE_EQ(e.time, 0.5);
  EXPECT_DOUBLE_EQ(e.kinetic, 16.5);
  EXPECT_DOUBLE_EQ(e.momentum_x, 6);
  EXPECT_DOUBLE_EQ(e.momentum_y, 0);
  EXPECT_DOUBLE_EQ(e.angular_momentum, -14.5);
  EXPECT_EQ(e.potential, 0) << "no gravity given";

  // P = −Σ m g·c over free particles: 2·(−(1·1 + 2·(−10))) + 1·(−(−1·1 + 0.5·(−10))) = 38 + 6.
  const EnergyRow g = compute_energy(s, {1, -10}, EnergyBudget{3, 1, 0.5, 0.25, 2});
  EXPECT_DOUBLE_EQ(g.potential, 44);
  EXPECT_DOUBLE_EQ(g.kinetic, 16.5);
  EXPECT_DOUBLE_EQ(g.total(), 16.5 + 44 + 3 + 1 + 0.5 + 0.25 - 2);
}

TEST(ComputeEnergy, EmptyAndAllFixedGiveZero) {
  EXPECT_EQ(compute_energy(particles(0)).kinetic, 0);
  Snapshot s = particles(1);
  set(s, 0, 1, 1, 1, 1, 1, 1, 1, Motion::Fixed);
  const EnergyRow e = compute_energy(s);
  EXPECT_EQ(e.kinetic, 0);
  EXPECT_EQ(e.momentum_x, 0);
  EXPECT_EQ(e.angular_momentum, 0);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
