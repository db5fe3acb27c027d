// A triangle dropped on a fixed floor under gravity comes to rest on it: the floor carries
// its weight and the penetration is what the penalty predicts.
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using Resting = test::BackendTest;

TEST_P(Resting, TriangleComesToRestOnFixedFloor) {
  const double p = 1e7, rho = 2000, g = 9.81;
  Scene s = test::empty_scene(p, rho, 0.5, 0.5);
  s.simulation.gravity = {0, -g};
  s.triangles.push_back(test::floor_triangle(-2, 2));
  // Base 0.2 on the floor side, height 0.1, dropped from 5 cm with a small spin.
  s.triangles.push_back(test::triangle({-0.1, 0.05}, {0.1, 0.05}, {0, 0.15}, {0, 0},
                                       Motion::Free, 0.5));
  auto solver = test::solver_for(s, GetParam());
  solver->advance(static_cast<std::int64_t>(1.0 / solver->dt()));
  Snapshot snap;
  solver->snapshot(snap, true);
  const double mass = rho * 0.5 * 0.2 * 0.1;
  EXPECT_LT(std::hypot(snap.vx[1], snap.vy[1]), 1e-3);
  EXPECT_LT(std::abs(snap.omega[1]), 1e-2);
  // Flat on its base: the centroid a third of the height above the floor, less the
  // penetration (a fraction of a percent of the size at this penalty).
  EXPECT_NEAR(snap.y[1], 0.1 / 3.0, 1e-3);
  EXPECT_NEAR(std::fmod(std::abs(snap.theta[1]), 2 * M_PI), 0.0, 1e-2);
  // The floor carries the weight.
  EXPECT_NEAR(snap.fy[0], -mass * g, 1e-2 * mass * g);
  EXPECT_NEAR(snap.fy[1], mass * g, 1e-2 * mass * g);
  EXPECT_EQ(snap.x[0], 0.0);  // fixed means fixed
}

// Floors of 4 and 10 m under grains of 0.2 m: checked in double (backend_test.hpp).
TRIDEM_INSTANTIATE_SOLVERS_IN_DOUBLE(Resting);

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
