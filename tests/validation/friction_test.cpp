// Friction acts on the contact's tangent only (docs/model.md, "Friction"): a symmetric
// normal impact is the same with and without friction; a tilted vertex sliding on a floor
// feels μ·f_n whichever way it slides; an equilateral grain on a slope flatter than
// atan μ holds. Each failed with the former edge-wise springs (11% slower rebound, 0.40
// against 0.75, creep of 1-3 cm/s).
#include "physics/contact_force.hpp"
#include "physics/restitution.hpp"
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using Friction = test::BackendTest;

/// Vertical speed after over before of an equilateral triangle (side 0.2 m) dropped
/// vertex-down at 1 m/s on a fixed floor, no gravity.
double vertex_drop_rebound(double mu, const test::SolverChoice& choice) {
  Scene s = test::empty_scene(1e8, 2000, mu, 0.0);
  s.materials[0].restitution = 0.6;
  // The same step with and without friction (the automatic one counts the tangential
  // springs only where μ > 0, and a different step would change the rebound by 2e-5).
  s.simulation.dt = 1e-6;
  s.triangles.push_back(test::floor_triangle(-1, 1));
  const double side = 0.2, h = side * std::sqrt(3.0) / 2;
  s.triangles.push_back(
      test::triangle({0, 1e-4}, {side / 2, 1e-4 + h}, {-side / 2, 1e-4 + h}, {0, -1}));
  auto solver = test::solver_for(s, choice);
  solver->advance(static_cast<std::int64_t>(0.02 / solver->dt()));
  Snapshot snap;
  solver->snapshot(snap, false);
  EXPECT_GT(snap.y[1], h * 2 / 3 + 1e-3) << "must have separated";
  return snap.vy[1];
}

TEST_P(Friction, SymmetricVertexDropIsTheSameWithAndWithoutFriction) {
  const double without = vertex_drop_rebound(0.0, GetParam());
  const double with = vertex_drop_rebound(0.5, GetParam());
  std::printf("vertex drop rebound: mu 0 %.9f, mu 0.5 %.9f m/s\n", without, with);
  EXPECT_GT(without, 0.3);
  EXPECT_NEAR(with, without, 1e-6 * without);
}

/// Friction at a tilted vertex pressed into a floor, sliding at v while pressing at v/2:
/// the pair's force with μ = 0.5 minus the one without, in units of the normal force.
struct Measured {
  double along, across;  ///< friction along the floor and across it, over the normal force
};
Measured tilted_vertex(double v) {
  using namespace physics;
  auto body = [](Triangle<double> t, Vec2<double> vel, double mass) {
    Body<double> b;
    b.tri = t;
    b.c = centroid(t);
    b.area = signed_area(t);
    b.v = vel;
    b.w = 0;
    b.mass = mass;
    return b;
  };
  // A floor as tall as the grain, so that the grain's own edges carry much of the load.
  const auto floor = body({{{0.3, 0}, {-0.3, 0}, {0, -0.3}}}, {}, 0);
  // An equilateral triangle of side 0.2 turned 20° from vertex-down, its vertex 1 mm deep.
  Triangle<double> t;
  const double r = 0.2 / std::sqrt(3.0), turn = 20 * M_PI / 180;
  for (int k = 0; k < 3; ++k) {
    const double angle = -M_PI / 2 + turn + k * 2 * M_PI / 3;
    t.v[k] = {r * std::cos(angle), r * std::sin(angle)};
  }
  const double lowest = std::min({t.v[0].y, t.v[1].y, t.v[2].y});
  for (auto& p : t.v) p.y += -lowest - 1e-3;
  // Fast enough to slide within the step (k_t·|v|·dt far above μ·f_n).
  const auto grain = body(t, {v, -0.5 * std::abs(v)}, 1);
  PairSlip<double> s0{}, s1{};
  const auto plain = pair_force(grain, floor, contact_law(1e6, 1e5, 0, 1), 1e-3, s0);
  const auto rough = pair_force(grain, floor, contact_law(1e6, 1e5, 0.5, 1), 1e-3, s1);
  const Vec2<double> friction = rough.force_a - plain.force_a;
  EXPECT_NEAR(plain.force_a.x, 0.0, 1e-12 * plain.force_a.y);  // the normal is vertical here
  return {friction.x / plain.force_a.y, friction.y / plain.force_a.y};
}

TEST(FrictionAtAVertex, IsTheSameBothWays) {
  // The former edge springs gave −0.433 along and 0.38 across (pushing along the normal)
  // one way, +0.5 and 0 the other.
  const Measured right = tilted_vertex(10.0), left = tilted_vertex(-10.0);
  EXPECT_NEAR(right.along, -0.5, 1e-9);
  EXPECT_NEAR(left.along, 0.5, 1e-9);
  EXPECT_NEAR(right.across, 0.0, 1e-9);
  EXPECT_NEAR(left.across, 0.0, 1e-9);
}

TEST_P(Friction, EquilateralGrainHoldsOnASlopeFlatterThanAtanMu) {
  // Gravity tilted 30° over a flat floor (tan 30° = 0.577 < μ = 0.7), the grain lying on
  // a side; after the normal contact settles it must neither creep nor rock.
  const double angle = M_PI / 6, g = 9.81;
  Scene s = test::empty_scene(1e8, 2000, 0.7, 0.0);
  s.materials[0].restitution = 0.3;
  s.simulation.gravity = {g * std::sin(angle), -g * std::cos(angle)};
  // A floor 1 m wide: in float (mixed precision) the contact's depth, about 0.2 µm here,
  // must stand above the rounding of the wall's vertices in the grain's frame, which a
  // 10 m floor does not allow (docs/model.md, mixed precision).
  s.triangles.push_back(test::floor_triangle(-0.5, 0.5));
  const double side = 0.1;
  s.triangles.push_back(test::triangle({-side / 2, 0}, {side / 2, 0},
                                       {0, side * std::sqrt(3.0) / 2}));
  auto solver = test::solver_for(s, GetParam());
  Snapshot snap;
  solver->advance(static_cast<std::int64_t>(0.1 / solver->dt()));
  solver->snapshot(snap, false);
  const double x0 = snap.x[1], theta0 = snap.theta[1];
  solver->advance(static_cast<std::int64_t>(0.4 / solver->dt()));
  solver->snapshot(snap, false);
  std::printf("grain on 30 deg slope, mu 0.7, over 0.4 s: dx %.3g m, dtheta %.3g rad, "
              "vx %.3g m/s, omega %.3g /s\n", snap.x[1] - x0, snap.theta[1] - theta0, snap.vx[1],
              snap.omega[1]);
  EXPECT_LT(std::abs(snap.x[1] - x0), 1e-6) << "creeps";
  EXPECT_LT(std::abs(snap.vx[1]), 1e-4);
  EXPECT_LT(std::abs(snap.theta[1] - theta0), 1e-5) << "rocks";
  EXPECT_LT(std::abs(snap.omega[1]), 1e-3);
}

TRIDEM_INSTANTIATE_SOLVERS(Friction);

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
