// The stable time step on a case computed by hand, and the refusal of an unstable dt.
// (docs/model.md, "The time step")
#include "core/particle_model.hpp"
#include "core/time_step.hpp"
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem {
namespace {

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

}  // namespace
}  // namespace tridem
