// The pieces of the step bound: the symplectic Euler limit of a damped oscillator, checked
// by iterating the scheme itself, and the largest mode of a body on springs.
#include "physics/stability.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem::physics {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// The amplitude after many steps of kick-then-drift on x'' = −ω²x − 2ζωx', from x = 1
/// (stopped once past 1e6, before it overflows).
double amplitude_after(double omega, double zeta, double dt, int steps = 20000) {
  double x = 1, v = 0;
  for (int i = 0; i < steps; ++i) {
    v += dt * (-omega * omega * x - 2 * zeta * omega * v);
    x += dt * v;
    if (std::abs(x) > 1e6) break;
  }
  return std::abs(x) + std::abs(v) / omega;
}

TEST(StabilityLimit, DampedOscillatorLimitIsSharp) {
  const double omega = 1000;
  for (double zeta : {0.0, 0.1, 0.5, 1.0}) {
    const double dt = symplectic_euler_limit(omega * omega, 2 * zeta * omega);
    EXPECT_NEAR(dt, 2 / omega * (std::sqrt(1 + zeta * zeta) - zeta), 1e-12 * dt);
    EXPECT_LT(amplitude_after(omega, zeta, 0.98 * dt), 10) << "zeta " << zeta;
    EXPECT_GT(amplitude_after(omega, zeta, 1.02 * dt), 1e3) << "zeta " << zeta;
  }
  EXPECT_TRUE(std::isinf(symplectic_euler_limit(0.0, 0.0)));
}

TEST(StabilityLimit, LargestModeOfABodyOnSprings) {
  // A unit square's worth of springs: an edge from (−1, −1) to (1, −1) with normal springs
  // only (outward normal −y): k·2 in y, lever arms −1..1 along x: ∫s² = 2/3 in rotation,
  // no coupling by symmetry.
  Sym3<double> s;
  add_edge_springs(s, Vec2d{-1, -1}, Vec2d{1, -1}, 3.0, 0.0);
  EXPECT_NEAR(s.yy, 6, 1e-12);
  EXPECT_NEAR(s.xx, 0, 1e-12);
  EXPECT_NEAR(s.tt, 2, 1e-12);
  EXPECT_NEAR(s.yt, 0, 1e-12);
  EXPECT_NEAR(largest_mode(s, 2.0, 0.5), 4, 1e-12);  // max(6/2, 2/0.5)
  // Tangential springs at lever arm 1 couple x and θ: [[k, k], [k, k]]·2 for unit masses.
  Sym3<double> t;
  add_edge_springs(t, Vec2d{-1, -1}, Vec2d{1, -1}, 0.0, 1.0);
  EXPECT_NEAR(t.xx, 2, 1e-12);
  EXPECT_NEAR(std::abs(t.xt), 2, 1e-12);
  EXPECT_NEAR(t.tt, 2, 1e-12);
  EXPECT_NEAR(largest_mode(t, 1.0, 1.0), 4, 1e-12);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::physics
