// Mixed precision (docs/model.md, "Precision"): in every precision the state is carried in
// double, so slow motion far from the origin is not lost to rounding, resting contact far
// from the origin settles, and float follows double in a pile where gravity and contacts
// matter. Each test runs on every backend, method and precision of the parametrised suites.
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using PrecisionTest = test::BackendTest;

// At x = 1 m a float position has a spacing of 1.2e-7 m; a step of 0.05 m/s × 1e-6 s is
// 5e-8 m, less than half of it, so a position integrated in float never moves.
TEST_P(PrecisionTest, SlowTriangleFarFromOriginMovesTheRightDistance) {
  Scene s = test::empty_scene();
  s.simulation.dt = 1e-6;
  s.triangles.push_back(test::triangle({0.95, 0.0}, {1.05, 0.0}, {1.0, 0.09}, {0.05, -0.03},
                                       Motion::Free, 0.05));
  auto solver = test::solver_for(s, GetParam());
  Snapshot start, end;
  solver->snapshot(start, false);
  const std::int64_t steps = 20000;
  solver->advance(steps);
  solver->snapshot(end, false);
  const double t = static_cast<double>(steps) * 1e-6;
  // 2e4 additions of a double step to 1 m: rounding of order 1e-12 m.
  EXPECT_NEAR(end.x[0] - start.x[0], 0.05 * t, 1e-10);
  EXPECT_NEAR(end.y[0] - start.y[0], -0.03 * t, 1e-10);
  EXPECT_NEAR(end.theta[0] - start.theta[0], 0.05 * t, 1e-10);
}

// A grain resting on a floor 100 m from the origin: in float, the absolute positions of its
// vertices are resolved to 7.6e-6 m there, a tenth of its penetration into the floor
// (7e-5 m at this penalty), so the contact force jumps by a tenth of the weight each time
// the rounding flips, and on main the grain jitters at centimetres per second. In the
// pair's own frame it rests as it does at the origin: the same bounds as
// Resting.TriangleComesToRestOnFixedFloor, and the same residual motion as at the origin.
// In float that residual is 4e-4 m/s and 6e-3 rad/s (measured, at every distance): float
// friction slips lose creep increments, and a floor 20 grains wide is resolved only to
// ε·its size inside pair_force, which also puts 2% of noise on its force (docs/model.md,
// "Precision", the table of what float still costs).
TEST_P(PrecisionTest, RestingContactFarFromOriginSettles) {
  const double p = 1e7, rho = 2000, g = 9.81;
  const double mass = rho * 0.5 * 0.2 * 0.1;
  auto rest = [&](Vec2d far) {
    Scene s = test::empty_scene(p, rho, 0.5, 0.5);
    s.simulation.gravity = {0, -g};
    TriangleSpec floor = test::floor_triangle(-2, 2);
    TriangleSpec grain = test::triangle({-0.1, 0.05}, {0.1, 0.05}, {0, 0.15});
    for (TriangleSpec* t : {&floor, &grain})
      for (Vec2d& v : t->vertices) v += far;
    s.triangles = {floor, grain};
    auto solver = test::solver_for(s, GetParam());
    solver->advance(static_cast<std::int64_t>(1.0 / solver->dt()));
    Snapshot snap;
    solver->snapshot(snap, true);
    return snap;
  };
  const Snapshot origin = rest({0, 0});
  const double origin_speed = std::hypot(origin.vx[1], origin.vy[1]);
  for (const Vec2d far : {Vec2d{100, 0}, Vec2d{-70, 70}}) {
    SCOPED_TRACE(testing::Message() << "floor at (" << far.x << ", " << far.y << ")");
    const Snapshot snap = rest(far);
    const double speed = std::hypot(snap.vx[1], snap.vy[1]);
    EXPECT_LT(speed, 1e-3);
    // Since the one-contact friction of issue 10 the float residual is about 1e-6 m/s at
    // the origin and 6e-6 m/s at these distances (the floor's float rounding in the pair's
    // frame), no longer 4e-4: the absolute slack is 1e-5 m/s, still 40 times below that
    // residual and 3000 times below the jitter this test was written against.
    EXPECT_NEAR(speed, origin_speed, 0.1 * origin_speed + 1e-5);
    EXPECT_LT(std::abs(snap.omega[1]), 1e-2);
    EXPECT_NEAR(snap.y[1] - far.y, 0.1 / 3.0, 1e-3);
    EXPECT_NEAR(snap.fy[1], mass * g, test::tolerance(GetParam(), 1e-2, 3e-2) * mass * g);
    // Contact points are reported where the contact is, not in the pair's frame.
    ASSERT_EQ(snap.contacts.size(), 1u);
    EXPECT_NEAR(snap.contacts[0].px, far.x, 0.1);
    EXPECT_NEAR(snap.contacts[0].py, far.y, 0.01);
  }
}

/// Statistics of the free grains of a pile: what a float run must reproduce of a double
/// one when the individual trajectories, being chaotic, do not agree.
struct PileStatistics {
  double mean_height = 0;
  double kinetic = 0;  ///< J/m
  double contacts = 0;
};

PileStatistics statistics(const Snapshot& s, double floor_y) {
  PileStatistics out;
  int grains = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.motion[i] != Motion::Free) continue;
    ++grains;
    out.mean_height += s.y[i] - floor_y;
    out.kinetic += 0.5 * s.mass[i] * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]) +
                   0.5 * s.inertia[i] * s.omega[i] * s.omega[i];
  }
  out.mean_height /= grains;
  out.contacts = static_cast<double>(s.contacts.size());
  return out;
}

/// The jostling pile (random shapes, friction, damping, gravity) moved 100 m from the
/// origin, where a float position is resolved to 7.6e-6 m.
Scene far_pile() {
  Scene s = test::jostling_pile(12, 6);
  for (TriangleSpec& t : s.triangles)
    for (Vec2d& v : t.vertices) v += Vec2d{100, 100};
  return s;
}

// Long enough for gravity and contacts to matter: the 72 grains start apart with random
// velocities, and in 8000 steps fall 0.137 m on average, lose 81% of their kinetic energy
// and make 80 contacts. Float on the CPU ends 4e-4 m, 4.4% and five contacts away from
// double (measured with the contact model of issue 10, one friction contact per pair; it
// was 6000 steps before, where that model leaves 57 contacts); the tolerances (2e-3 m,
// 10%, 10%) leave room for the GPU's other rounding and the pile's chaos. Without gravity
// the same run (6000 steps, former contact model) ended 0.124 m higher with 62% less
// kinetic energy and 15 contacts: a float that ignored gravity, lost motion or dropped
// contacts would fail every one of them.
TEST_P(PrecisionTest, FloatFollowsDoubleInASettlingPile) {
  const Scene scene = far_pile();
  const double floor_y = 100 - 0.06;
  const std::int64_t steps = 8000;
  const Snapshot start = test::run_to(scene, Backend::Cpu, 0);
  const Snapshot reference = test::run_to(scene, Backend::Cpu, steps);
  const Snapshot tried = test::run_to(scene, GetParam().backend, steps, GetParam().precision,
                                      GetParam().method);
  const PileStatistics s0 = statistics(start, floor_y);
  const PileStatistics ref = statistics(reference, floor_y);
  const PileStatistics got = statistics(tried, floor_y);
  // Gravity and contacts matter over this run: the pile fell, lost most of its kinetic
  // energy, and its grains touch.
  ASSERT_LT(ref.mean_height, s0.mean_height - 0.02);
  ASSERT_LT(ref.kinetic, 0.5 * s0.kinetic);
  ASSERT_GT(ref.contacts, 60);
  std::printf("settling pile: height %.4f -> %.4f (float %.4f) m, kinetic %.4g -> %.4g (float "
              "%.4g), contacts %g (float %g)\n", s0.mean_height, ref.mean_height, got.mean_height,
              s0.kinetic, ref.kinetic, got.kinetic, ref.contacts, got.contacts);
  EXPECT_NEAR(got.mean_height, ref.mean_height, 2e-3);
  EXPECT_NEAR(got.kinetic, ref.kinetic, 0.1 * ref.kinetic);
  EXPECT_NEAR(got.contacts, ref.contacts, 0.1 * ref.contacts);
}

TRIDEM_INSTANTIATE_SOLVERS(PrecisionTest);

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
