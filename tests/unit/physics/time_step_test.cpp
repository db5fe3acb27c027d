// The stable time step on a case computed by hand, and the refusal of an unstable dt.
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

TEST(TimeStep, CriticalStepOfRightTriangleByHand) {
  const Scene s = right_triangle_scene();
  const ParticleModel m = build_particle_model(s);
  // Area 6, m = 6000; offsets from the centroid (1, 4/3): Σ|r|² = 50/3, I = m·Σ/12.
  EXPECT_DOUBLE_EQ(m.mass[0], 6000.0);
  EXPECT_NEAR(m.inertia[0], 6000.0 * (50.0 / 3.0) / 12.0, 1e-9);
  // k = 3·p·L/h = 3e6·5/2.4 (L = 5, h = 2·6/5); m_min = min(m, I/r_max²), the farthest
  // vertex being (0, 4) with |r|² = 1 + (8/3)² = 73/9.
  const double k = 3e6 * 5.0 / 2.4;
  const double m_min = std::min(6000.0, m.inertia[0] / (73.0 / 9.0));
  const TimeStep ts = estimate_time_step(s, m);
  EXPECT_NEAR(ts.critical, 2 * std::sqrt(m_min / k), 1e-12);
  EXPECT_TRUE(ts.automatic);
  EXPECT_NEAR(ts.chosen, 0.1 * ts.critical, 1e-15);
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
