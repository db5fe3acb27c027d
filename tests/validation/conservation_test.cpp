// A dense cloud of colliding triangles with friction and damping, no gravity and no
// walls: every pair force acts at one point on both bodies, so linear and angular momentum
// are conserved to rounding, while friction and damping dissipate energy.
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"
#include "tridem/output.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using Conservation = test::BackendTest;

Scene colliding_cloud(int side) {
  Scene s = test::empty_scene(1e7, 1000, 0.5, 0.1);
  // The step the collision count below was chosen with (0.1 of the former estimate, about
  // 0.3 of today's proven dt_crit).
  s.simulation.safety = 0.3;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  const double pitch = 0.12, r = 0.05;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const Vec2d c{i * pitch, j * pitch};
      const double a0 = 3.14159 * u(rng);
      TriangleSpec t;
      for (int k = 0; k < 3; ++k) {
        const double a = a0 + k * 2.0943951023931953 + 0.3 * u(rng);
        t.vertices[k] = {c.x + r * std::cos(a), c.y + r * std::sin(a)};
      }
      if ((t.vertices[1].x - t.vertices[0].x) * (t.vertices[2].y - t.vertices[0].y) -
              (t.vertices[2].x - t.vertices[0].x) * (t.vertices[1].y - t.vertices[0].y) < 0)
        std::swap(t.vertices[1], t.vertices[2]);
      t.velocity = {2 * u(rng), 2 * u(rng)};
      t.angular_velocity = 20 * u(rng);
      s.triangles.push_back(t);
    }
  return s;
}

TEST_P(Conservation, CollidingCloudConservesMomentum) {
  const Scene s = colliding_cloud(12);
  auto solver = test::solver_for(s, GetParam());
  Snapshot snap;
  solver->snapshot(snap, false);
  const EnergyRow before = compute_energy(snap);
  double momentum_scale = 0, angular_scale = 0;
  for (std::size_t i = 0; i < snap.size(); ++i) {
    momentum_scale += snap.mass[i] * std::hypot(snap.vx[i], snap.vy[i]);
    angular_scale += snap.mass[i] * std::hypot(snap.x[i], snap.y[i]) *
                         std::hypot(snap.vx[i], snap.vy[i]) +
                     snap.inertia[i] * std::abs(snap.omega[i]);
  }
  std::size_t contacts = 0;
  double kinetic = before.kinetic;
  for (int chunk = 0; chunk < 40; ++chunk) {  // contacts counted every 50 steps
    solver->advance(50);
    solver->snapshot(snap, true);
    contacts += snap.contacts.size();
    const EnergyRow now = compute_energy(snap);
    // A pair's forces are equal and opposite exactly, but each particle's sum is rounded
    // in the pairs' precision before the double integration: in float that leaves about
    // 2e-11 of the scale after 2000 steps (measured); 1e-10 allowed.
    const double relative = test::tolerance(GetParam(), 1e-12, 1e-10);
    EXPECT_NEAR(now.momentum_x, before.momentum_x, relative * momentum_scale);
    EXPECT_NEAR(now.momentum_y, before.momentum_y, relative * momentum_scale);
    EXPECT_NEAR(now.angular_momentum, before.angular_momentum, relative * angular_scale);
    kinetic = now.kinetic;
  }
  EXPECT_GT(contacts, 100u) << "the cloud must actually collide";
  EXPECT_LT(kinetic, 0.9 * before.kinetic) << "friction and damping must dissipate";
}

TRIDEM_INSTANTIATE_SOLVERS(Conservation);

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
