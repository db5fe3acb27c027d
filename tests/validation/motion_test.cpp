// Motion without contact: free fall and spin under symplectic Euler, prescribed walls that
// follow their velocity exactly and push what they meet, and Cundall local damping.
#include "physics/integrate.hpp"
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using MotionTest = test::BackendTest;  // not "Motion": that is the enum tridem::Motion

TEST_P(MotionTest, FreeFallAndSpinFollowTheAnalyticSolution) {
  Scene s = test::empty_scene();
  s.simulation.gravity = {0.5, -9.81};
  s.simulation.dt = 1e-5;
  s.triangles.push_back(test::triangle({0, 0}, {0.1, 0}, {0, 0.1}, {1.0, 2.0}, Motion::Free, 3.0));
  auto solver = test::solver_for(s, GetParam());
  Snapshot start, end;
  solver->snapshot(start, false);
  const std::int64_t steps = 50000;
  solver->advance(steps);
  solver->snapshot(end, false);
  const double t = end.time, dt = 1e-5;
  EXPECT_NEAR(t, steps * dt, 1e-10);
  // Symplectic Euler: x_n = x0 + v0·t + g·t·(t + dt)/2 exactly for constant g.
  EXPECT_NEAR(end.x[0], start.x[0] + 1.0 * t + 0.5 * 0.5 * t * (t + dt), 1e-9);
  EXPECT_NEAR(end.y[0], start.y[0] + 2.0 * t - 0.5 * 9.81 * t * (t + dt), 1e-9);
  EXPECT_NEAR(end.vy[0], 2.0 - 9.81 * t, 1e-9);
  EXPECT_NEAR(end.theta[0], 3.0 * t, 1e-10);  // 5e4 additions of rounding
  EXPECT_NEAR(end.omega[0], 3.0, 1e-12);
}

TEST_P(MotionTest, PrescribedWallFollowsItsVelocityAndPushesAGrain) {
  Scene s = test::empty_scene(1e7, 1000, 0.0, 0.2);
  // A plate moving right at 0.5 m/s and turning slowly; a grain at rest in its way.
  s.triangles.push_back(test::triangle({-0.2, -0.5}, {0.0, 0.0}, {-0.2, 0.5}, {0.5, 0},
                                       Motion::Prescribed, 0.0));
  s.triangles.push_back(test::triangle({0.05, -0.05}, {0.15, 0.0}, {0.05, 0.05}));
  s.triangles.push_back(test::triangle({5, 5}, {5.1, 5}, {5, 5.1}, {0, 0}, Motion::Prescribed,
                                       2.0));
  auto solver = test::solver_for(s, GetParam());
  Snapshot start, end;
  solver->snapshot(start, false);
  solver->advance(static_cast<std::int64_t>(0.4 / solver->dt()));
  solver->snapshot(end, false);
  EXPECT_NEAR(end.x[0] - start.x[0], 0.5 * end.time, 1e-9);  // contact did not slow it
  EXPECT_EQ(end.y[0], start.y[0]);
  EXPECT_NEAR(end.theta[2], 2.0 * end.time, 1e-9);
  EXPECT_EQ(end.x[2], start.x[2]);
  // The grain was hit and pushed ahead of the plate.
  EXPECT_GT(end.vx[1], 0.4);
  EXPECT_GT(end.x[1], start.x[1] + 0.05);
}

TEST(Motion, LocalDampingOpposesVelocityByAFractionOfTheForce) {
  EXPECT_DOUBLE_EQ(physics::local_damping(10.0, 1.0, 0.3, 0.01), 7.0);     // force along v: less
  EXPECT_DOUBLE_EQ(physics::local_damping(-10.0, 1.0, 0.3, 0.01), -13.0);  // against v: more
  EXPECT_DOUBLE_EQ(physics::local_damping(10.0, 0.0, 0.3, 0.01), 10.0);    // at rest: unchanged
}

// A velocity of rounding noise beside the step's change (force 1e5 N/m, 0.4 m/s in one
// step) is rest: its sign does not decide +-alpha of the force. Just above the ratio, it
// does.
TEST(Motion, LocalDampingTreatsANoiseVelocityAsRest) {
  const double response = 4e-6;  // m/s per N/m in one step: 1e5 N/m gives 0.4 m/s
  const double change = 1e5 * response;
  for (double noise : {1e-13, -1e-13, 0.5 * physics::kDampingRestRatio * change})
    EXPECT_DOUBLE_EQ(physics::local_damping(-1e5, noise, 0.2, response), -1e5) << noise;
  const double moving = 2 * physics::kDampingRestRatio * change;
  EXPECT_DOUBLE_EQ(physics::local_damping(-1e5, moving, 0.2, response), -1.2e5);
  EXPECT_DOUBLE_EQ(physics::local_damping(-1e5, -moving, 0.2, response), -0.8e5);
}

TEST_P(MotionTest, LocalDampingSettlesABouncingGrainFaster) {
  auto kinetic_after = [choice = GetParam()](double alpha) {
    Scene s = test::empty_scene(1e6, 1000);
    s.simulation.gravity = {0, -9.81};
    s.simulation.local_damping = alpha;
    s.triangles.push_back(test::floor_triangle(-1, 1));
    s.triangles.push_back(test::triangle({-0.05, 0.05}, {0.05, 0.05}, {0, 0.12}));
    const Snapshot snap = test::run_to(s, choice.backend, 20000, choice.precision, choice.method);
    return 0.5 * snap.mass[1] * (snap.vx[1] * snap.vx[1] + snap.vy[1] * snap.vy[1]);
  };
  const double undamped = kinetic_after(0.0), damped = kinetic_after(0.7);
  EXPECT_GT(undamped, 1e-4);  // an elastic grain keeps bouncing
  EXPECT_LT(damped, 1e-3 * undamped);
}

TRIDEM_INSTANTIATE_SOLVERS(MotionTest);

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
