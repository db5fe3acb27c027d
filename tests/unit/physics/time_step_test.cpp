// The stable time step on a case computed by hand, and the refusal of an unstable dt.
// (docs/model.md, "The time step")
#include "core/time_step.hpp"
#include "core/particle_model.hpp"
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

Scene right_triangle_scene() {
  Scene s = test::empty_scene(1e6, 1000);
  s.source = "hand.toml";
  s.triangles.push_back(test::triangle({0, 0}, {3, 0}, {0, 4}));
  return s;
}

// An equilateral triangle of side a alone meets, at worst, copies of itself on all three
// edges: per metre of edge k = 2·3p(1/h + 1/h) (both roles; 2 for two free bodies), h =
// a√3/2. Translation: k·a·Σ n nᵀ = 1.5·k·a; rotation: 3·k·a³/12 over I = m·a²/12, i.e.
// 3·k·a/m, the larger. Undamped: dt_crit = 2/ω.
TEST(TimeStep, CriticalStepOfEquilateralTriangleByHand) {
  Scene s = test::empty_scene(1e6, 1000);
  const double a = 0.2, h = a * std::sqrt(3.0) / 2;
  s.triangles.push_back(test::triangle({0, 0}, {a, 0}, {a / 2, h}));
  const ParticleModel m = build_particle_model(s);
  const double k = 2 * 3e6 * (2 / h), omega2 = 3 * k * a / m.mass[0];
  const TimeStep ts = estimate_time_step(s, m);
  EXPECT_NEAR(ts.critical, 2 / std::sqrt(omega2), 1e-12 * ts.critical);
  EXPECT_TRUE(ts.automatic);
  EXPECT_NEAR(ts.chosen, 0.1 * ts.critical, 1e-15);
  EXPECT_EQ(ts.limit.particle, 0);
  EXPECT_TRUE(ts.limit.partner_free);

  // Damping: each edge's dashpot 2ζ√(m_eff·k_pair) (one partner per edge: the scene has
  // one particle; m_eff = m/2 against a copy) is 2ζ√(m_eff/k_pair) times its springs,
  // k_pair = k·a/2, so λ_C is that times λ_K.
  s.materials[0].damping = 0.3;
  const double lambda_c = 2 * 0.3 * std::sqrt(0.5 * m.mass[0] / (k * a / 2)) * omega2;
  EXPECT_NEAR(estimate_time_step(s, m).critical,
              4 / (lambda_c + std::sqrt(lambda_c * lambda_c + 4 * omega2)), 1e-9 * ts.critical);
  EXPECT_LT(estimate_time_step(s, m).critical, ts.critical);

  // A fixed wall thinner than the grain stiffens its contact and shortens the step.
  s.materials[0].damping = 0;
  s.triangles.push_back(test::triangle({-1, -0.01}, {1, -0.01}, {0, -0.001}, {}, Motion::Fixed));
  const TimeStep walled = estimate_time_step(s, build_particle_model(s));
  EXPECT_LT(walled.critical, 0.5 * ts.critical);
  EXPECT_FALSE(walled.limit.partner_free);
  EXPECT_EQ(walled.limit.partner, 1);
}

/// A square body of side a centred at c, cut along a diagonal into two members.
void add_square_body(Scene& s, Vec2d c, double a, Motion motion = Motion::Free) {
  const double h = a / 2;
  const Vec2d p0 = c + Vec2d{-h, -h}, p1 = c + Vec2d{h, -h}, p2 = c + Vec2d{h, h},
              p3 = c + Vec2d{-h, h};
  BodySpec b;
  b.first = s.triangles.size();
  b.count = 2;
  b.motion = motion;
  s.triangles.push_back(test::triangle(p0, p1, p2, {}, motion));
  s.triangles.push_back(test::triangle(p0, p2, p3, {}, motion));
  s.bodies.push_back(b);
}

// A square body of side a alone meets, at worst, copies of itself on its four outer
// edges; its diagonal is inside it and no partner reaches it. The members' heights over
// the outer edges are a (not their smallest, a/√2 over the diagonal), so per metre k =
// 2·3p(1/a + 1/a) = 12p/a. Frictionless: normal springs only; translation 2·k·a/M,
// rotation 4·k·a³/12 over I = M·a²/6, i.e. 2·k·a/M too. Undamped: dt_crit = 2/ω with the
// body's mass, not a member's.
TEST(TimeStep, CriticalStepOfSquareBodyByHand) {
  Scene s = test::empty_scene(1e6, 1000);
  const double a = 0.2;
  add_square_body(s, {0.3, -0.1}, a);
  const ParticleModel m = build_particle_model(s);
  const double mass = 1000 * a * a, k = 12e6 / a, omega2 = 2 * k * a / mass;
  const TimeStep ts = estimate_time_step(s, m);
  EXPECT_NEAR(ts.critical, 2 / std::sqrt(omega2), 1e-12 * ts.critical);
  EXPECT_EQ(ts.limit.body, 0);
  EXPECT_EQ(ts.limit.body_members, 2);
  EXPECT_NE(ts.describe().find("body 0 (2 triangles"), std::string::npos) << ts.describe();

  // The same two triangles as two single grains: each is bounded on its own mass and
  // heights, a shorter step.
  Scene loose = s;
  loose.bodies.clear();
  EXPECT_LT(estimate_time_step(loose, build_particle_model(loose)).critical, 0.8 * ts.critical);

  // A member with every edge inside its body (the middle of a fan) touches nothing: it
  // neither sets the thinnest partner nor a limit of its own.
  Scene fan = test::empty_scene(1e6, 1000);
  BodySpec b;
  b.count = 4;
  const Vec2d o{0, 0}, p{a, 0}, q{a / 2, a * std::sqrt(3.0) / 2};
  const Vec2d pq = (p + q) / 2.0, qo = (q + o) / 2.0, op = (o + p) / 2.0;
  fan.triangles = {test::triangle(op, pq, qo), test::triangle(o, op, qo), test::triangle(op, p, pq),
                   test::triangle(qo, pq, q)};
  fan.bodies.push_back(b);
  const TimeStep whole = estimate_time_step(fan, build_particle_model(fan));
  EXPECT_NE(whole.limit.partner, 0) << whole.describe();
  EXPECT_NE(whole.limit.particle, 0) << whole.describe();
}

TEST(TimeStep, GivenStepAboveCriticalIsRefusedUnlessForced) {
  Scene s = right_triangle_scene();
  const ParticleModel m = build_particle_model(s);
  s.simulation.dt = 10 * estimate_time_step(s, m).critical;
  const TimeStep ts = estimate_time_step(s, m);
  try {
    check_time_step(s, ts, false);
    FAIL() << "no refusal";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("hand.toml"), std::string::npos) << what;
    EXPECT_NE(what.find("dt_crit"), std::string::npos) << what;
    EXPECT_NE(what.find("--force"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(check_time_step(s, ts, true));
  s.simulation.dt = 0.5 * ts.critical;
  EXPECT_NO_THROW(check_time_step(s, estimate_time_step(s, m), false));
}

TEST(TimeStep, DegenerateTriangleIsRefusedNamingTheParticle) {
  Scene s = right_triangle_scene();
  s.triangles.push_back(test::triangle({0, 0}, {1, 1}, {2, 2}));
  try {
    build_particle_model(s);
    FAIL() << "no refusal";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("particle id 1"), std::string::npos) << e.what();
  }
}

TEST(TimeStep, ClockwiseTriangleGetsPositiveAreaAndSameMass) {
  Scene s = right_triangle_scene();
  s.triangles.push_back(test::triangle({0, 0}, {0, 4}, {3, 0}));
  const ParticleModel m = build_particle_model(s);
  EXPECT_DOUBLE_EQ(m.area[1], 6.0);
  EXPECT_DOUBLE_EQ(m.inertia[1], m.inertia[0]);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
