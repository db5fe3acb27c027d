// A block on a 30° incline (gravity tilted by 30° over a flat fixed floor): with μ < tan θ
// it slides with a = g(sin θ − μ cos θ); with μ > tan θ the friction spring holds it.
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using Incline = test::BackendTest;

constexpr double kAngle = M_PI / 6, kG = 9.81;

struct Slide {
  double acceleration;  ///< measured along the slope
  double displacement;  ///< over the measuring window
};

Slide slide(double mu, const test::SolverChoice& choice) {
  Scene s = test::empty_scene(1e8, 2000, mu, 0.3);
  s.simulation.gravity = {kG * std::sin(kAngle), -kG * std::cos(kAngle)};
  s.triangles.push_back(test::floor_triangle(-5, 5));
  // A flat block lying on its long edge, just touching the floor.
  s.triangles.push_back(test::triangle({-0.1, 0}, {0.1, 0}, {0, 0.05}));
  auto solver = test::solver_for(s, choice);
  Snapshot snap;
  // Let the normal contact settle, then measure v over a fixed window.
  const auto settle = static_cast<std::int64_t>(0.1 / solver->dt());
  const auto window = static_cast<std::int64_t>(0.4 / solver->dt());
  solver->advance(settle);
  solver->snapshot(snap, false);
  const double v0 = snap.vx[1], x0 = snap.x[1], t0 = snap.time;
  solver->advance(window);
  solver->snapshot(snap, false);
  return {(snap.vx[1] - v0) / (snap.time - t0), snap.x[1] - x0};
}

TEST_P(Incline, BlockSlidesWithCoulombAcceleration) {
  const double mu = 0.3;
  const double expected = kG * (std::sin(kAngle) - mu * std::cos(kAngle));
  const Slide r = slide(mu, GetParam());
  EXPECT_NEAR(r.acceleration, expected, 0.05 * expected);
}

TEST_P(Incline, FrictionlessBlockSlidesWithGSinTheta) {
  const double expected = kG * std::sin(kAngle);
  EXPECT_NEAR(slide(0.0, GetParam()).acceleration, expected, 0.05 * expected);
}

TEST_P(Incline, BlockHoldsWhenFrictionExceedsSlope) {
  const Slide r = slide(0.8, GetParam());  // tan 30° = 0.577
  EXPECT_LT(std::abs(r.displacement), 1e-5);
  EXPECT_LT(std::abs(r.acceleration), 1e-3);
}

// Floors of 4 and 10 m under grains of 0.2 m: checked in double (backend_test.hpp).
TRIDEM_INSTANTIATE_SOLVERS_IN_DOUBLE(Incline);

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
