// Head-on impact of two triangles meeting face to face: without damping the restitution is
// 1; with the legacy damping ratio ζ it is the linear spring-dashpot value
// exp(−πζ/√(1−ζ²)), the restitution ζ now stands for (docs/model.md, "Damping").
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using Impact = test::BackendTest;

/// Relative speed after over before for two equal right triangles whose vertical faces
/// meet, approaching at 2 m/s.
double restitution(double damping, double dt, const test::SolverChoice& choice) {
  Scene s = test::empty_scene(1e8, 1000, 0.0, damping);
  if (dt > 0) s.simulation.dt = dt;
  const double gap = 0.005;
  s.triangles.push_back(test::triangle({-gap, -0.5}, {-gap, 0.5}, {-1 - gap, 0}, {1, 0}));
  s.triangles.push_back(test::triangle({gap, 0.5}, {gap, -0.5}, {1 + gap, 0}, {-1, 0}));
  auto solver = test::solver_for(s, choice);
  Snapshot snap;
  // Contact lasts about π/ω with ω = √(6p/m_eff) ≈ 1.5e3 /s: 2 ms; run well past it.
  const auto steps = static_cast<std::int64_t>(0.03 / solver->dt());
  solver->advance(steps);
  solver->snapshot(snap, false);
  EXPECT_GT(snap.x[1] - snap.x[0], 2.0 / 3.0) << "the triangles must have separated";
  // A symmetric impact: no sideways motion or spin, to rounding. In float the pair's
  // forces are rounded to 6e-8 of their size, about 1e3 N/m here over the 2 ms contact:
  // 2e-7 m/s and rad/s measured, 1e-6 allowed.
  EXPECT_NEAR(snap.vy[0], 0.0, test::tolerance(choice, 1e-9, 1e-6));
  EXPECT_NEAR(snap.omega[0], 0.0, test::tolerance(choice, 1e-9, 1e-6));
  return (snap.vx[1] - snap.vx[0]) / 2.0;
}

TEST_P(Impact, UndampedHeadOnImpactKeepsRestitutionOne) {
  EXPECT_NEAR(restitution(0.0, 0, GetParam()), 1.0, 0.02);
}

TEST_P(Impact, DampingGivesPredictedRestitution) {
  // A step of about 1/200 of the contact time, so that the model, not the integrator's
  // error at the default step (about 20 steps per contact), is what is measured.
  for (double zeta : {0.05, 0.2, 0.5}) {
    const double predicted = std::exp(-M_PI * zeta / std::sqrt(1 - zeta * zeta));
    const double e = restitution(zeta, 1e-5, GetParam());
    EXPECT_LT(e, 1.0);
    EXPECT_NEAR(e, predicted, 0.03 * predicted) << "zeta " << zeta;
  }
}

TRIDEM_INSTANTIATE_SOLVERS(Impact);

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
