// The time step holds where contacts press on every side: packings of equilateral
// triangles, undamped and frictionless, keep their energy bounded for 20,000 steps at the
// largest step tridem accepts (automatic with safety 1, or dt = dt_crit given), and the
// same packings go unstable at twice it, so the bound is not needlessly small. A grain
// resting on a thin fixed floor stays put with the automatic step: the floor's height
// enters the bound.
#include "core/particle_model.hpp"
#include "core/time_step.hpp"
#include "support/backend_test.hpp"
#include "support/lattice_scenes.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"
#include <cstdio>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

double critical_step(const Scene& s) {
  return estimate_time_step(s, build_particle_model(s)).critical;
}

/// What a run did: stopped by the blow-up checks, or the largest kinetic energy over its
/// first half and over its second half (a stable packing trades elastic and kinetic
/// energy back and forth at one level; an unstable one grows exponentially).
struct Outcome {
  bool blew_up = false;
  std::string message;
  double early = 0, late = 0;
};

Outcome run(const Scene& s, const test::SolverChoice& choice, std::int64_t steps,
            bool force = false) {
  SolverConfig config;
  config.force = force;
  auto solver = test::solver_for(s, choice, config);
  Outcome out;
  Snapshot snap;
  const std::int64_t chunk = 250;
  try {
    for (std::int64_t done = 0; done < steps; done += chunk) {
      solver->advance(chunk);
      solver->snapshot(snap, false);
      const double kinetic = compute_energy(snap).kinetic;
      if (done + chunk <= steps / 2) out.early = std::max(out.early, kinetic);
      if (done >= steps / 2) out.late = std::max(out.late, kinetic);
    }
  } catch (const RunError& e) {
    out.blew_up = true;
    out.message = e.what();
  }
  return out;
}

/// Stable: no blow-up, and the energy of the second half no larger than in the first (the
/// elastic energy of the squeeze turns into vibration and back).
void expect_stable(const Outcome& o, const char* what) {
  EXPECT_FALSE(o.blew_up) << what << ": " << o.message;
  EXPECT_GT(o.early, 0) << what << ": the squeeze must set the packing vibrating";
  EXPECT_LT(o.late, 2 * o.early) << what << ": energy grows";
}

/// Unstable: stopped by the blow-up checks, or the energy has grown tenfold.
void expect_unstable(const Outcome& o, const char* what) {
  EXPECT_TRUE(o.blew_up || o.late > 10 * o.early)
      << what << ": still stable, early " << o.early << " J/m, late " << o.late << " J/m";
}

using StepStability = test::BackendTest;

void check_packing(Scene s, const test::SolverChoice& choice) {
  const double dt_crit = critical_step(s);
  s.simulation.safety = 1;
  expect_stable(run(s, choice, 20000), "automatic step, safety 1");
  s.simulation.dt = dt_crit;
  expect_stable(run(s, choice, 20000), "dt = dt_crit");
  s.simulation.dt = 2 * dt_crit;
  EXPECT_THROW(test::solver_for(s, choice), RunError) << "twice dt_crit must be refused";
  expect_unstable(run(s, choice, 20000, true), "dt = 2 dt_crit (forced)");
}

TEST_P(StepStability, ChannelHoldsAtTheAcceptedStepAndNotAtTwiceIt) {
  check_packing(test::channel_packing(), GetParam());
}

TEST_P(StepStability, HexagonHoldsAtTheAcceptedStepAndNotAtTwiceIt) {
  check_packing(test::hexagon_packing(), GetParam());
}

/// An equilateral grain of side 0.1 m landing flat at 5 cm/s on a fixed floor `thickness`
/// thick, under gravity, with friction and damping.
Scene grain_on_thin_floor(double thickness) {
  Scene s = test::empty_scene(1e7, 2000, 0.5, 0.2);
  s.simulation.gravity = {0, -9.81};
  s.triangles.push_back(test::triangle({1, 0}, {-1, 0}, {0.2, -thickness}, {}, Motion::Fixed));
  const double a = 0.1, h = a * std::sqrt(3.0) / 2;
  s.triangles.push_back(test::triangle({-a / 2, 0}, {a / 2, 0}, {0, h}, {0, -0.05}));
  return s;
}

// With the default safety, and with safety 1 (the largest automatic step).
TEST_P(StepStability, GrainRestsOnThinFloorsWithTheAutomaticStep) {
  for (double thickness : {1e-4, 1e-5})
    for (double safety : {0.1, 1.0}) {
      Scene s = grain_on_thin_floor(thickness);
      s.simulation.safety = safety;
      SCOPED_TRACE(testing::Message() << thickness << " m thick floor, safety " << safety);
      auto solver = test::solver_for(s, GetParam());
      ASSERT_NO_THROW(solver->advance(20000));
      Snapshot snap;
      solver->snapshot(snap, false);
      const double h = 0.1 * std::sqrt(3.0) / 2;
      EXPECT_NEAR(snap.y[1], h / 3, 1e-3 * h);
      EXPECT_LT(std::hypot(snap.vx[1], snap.vy[1]), 1e-2);
    }
}

TRIDEM_INSTANTIATE_SOLVERS(StepStability);

/// A block of 4 x 3 free square bodies (two triangles each, side a) in a frame of fixed
/// ones, every square enlarged by `squeeze` about its centre so that each presses on its
/// neighbours, shaken: the packing of bodies whose step core/time_step bounds per body.
Scene square_body_packing(double squeeze = 0.01, double a = 0.1) {
  Scene s = test::lattice_scene();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int pass = 0; pass < 2; ++pass)
    for (int j = -1; j <= 3; ++j)
      for (int k = -1; k <= 4; ++k) {
        const bool inner = j >= 0 && j < 3 && k >= 0 && k < 4;
        if (inner != (pass == 0)) continue;
        const Motion motion = inner ? Motion::Free : Motion::Fixed;
        const Vec2d c{k * a, j * a};
        const double h = a * (1 + squeeze) / 2;
        BodySpec b;
        b.first = s.triangles.size();
        b.count = 2;
        b.motion = motion;
        if (inner) {
          b.velocity = {0.01 * u(rng), 0.01 * u(rng)};
          b.angular_velocity = 0.01 / a * u(rng);
        }
        const Vec2d p0 = c + Vec2d{-h, -h}, p1 = c + Vec2d{h, -h}, p2 = c + Vec2d{h, h},
                    p3 = c + Vec2d{-h, h};
        s.triangles.push_back(test::triangle(p0, p1, p2, {}, motion));
        s.triangles.push_back(test::triangle(p0, p2, p3, {}, motion));
        s.bodies.push_back(b);
      }
  return s;
}

// Bodies are bounded as bodies (their mass and inertia, their outer edges), and the
// packing holds at the step that bound accepts; the former per-member bound was smaller.
TEST(StepStabilityBodies, SquareBodiesHoldAtTheAcceptedStepAndNotAtTwiceIt) {
  Scene s = square_body_packing();
  const double dt_crit = critical_step(s);
  EXPECT_GE(estimate_time_step(s, build_particle_model(s)).limit.body, 0);
  s.simulation.safety = 1;
  expect_stable(run(s, Backend::Cpu, 20000), "automatic step, safety 1");
  s.simulation.dt = 2 * dt_crit;
  expect_unstable(run(s, Backend::Cpu, 20000, true), "dt = 2 dt_crit (forced)");
}

// The wall's thickness sets dt_crit, and the refusal of a larger dt says so.
TEST(StepLimit, ThinWallSetsTheStepAndIsNamed) {
  Scene s = grain_on_thin_floor(1e-4);
  s.source = "thin.toml";
  const TimeStep ts = estimate_time_step(s, build_particle_model(s));
  EXPECT_TRUE(ts.limit.thin_wall());
  EXPECT_EQ(ts.limit.particle, 1);
  EXPECT_EQ(ts.limit.partner, 0);
  EXPECT_LT(ts.critical, 0.2 * critical_step(grain_on_thin_floor(1e-2)));
  s.simulation.dt = 1.5 * ts.critical;
  try {
    check_time_step(s, estimate_time_step(s, build_particle_model(s)), false);
    FAIL() << "no refusal";
  } catch (const RunError& e) {
    const std::string what = e.what();
    for (const char* part : {"thin.toml", "[simulation] dt", "dt_crit", "particle 1",
                             "fixed or prescribed particle 0", "thin wall", "--force"})
      EXPECT_NE(what.find(part), std::string::npos) << part << " not in: " << what;
  }
}

// The blow-up message names dt_crit and its cause and never advises a stiffer contact.
TEST(StepLimit, BlowUpMessageNamesTheStepLimitNotThePenalty) {
  Scene s = grain_on_thin_floor(1e-4);
  s.simulation.dt = 20 * critical_step(s);
  const Outcome o = run(s, Backend::Cpu, 20000, true);
  ASSERT_TRUE(o.blew_up);
  for (const char* part :
       {"blow-up at step", "dt_crit", "lower dt", "make the thin wall (particle 0) thicker"})
    EXPECT_NE(o.message.find(part), std::string::npos) << part << " not in: " << o.message;
  EXPECT_EQ(o.message.find("raise the penalty"), std::string::npos) << o.message;
}

/// The former estimate, 2·√(m_min/k), k = 3·p·L_max/h_min over the free particles.
double former_critical_step(const Scene& s) {
  const ParticleModel m = build_particle_model(s);
  double l = 0, h = 1e300, m_min = 1e300;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m.motion[i] != Motion::Free) continue;
    l = std::max(l, m.longest_edge[i]);
    h = std::min(h, m.smallest_height[i]);
    double r2 = 0;
    for (const Vec2d& r : m.offsets[i]) r2 = std::max(r2, dot(r, r));
    m_min = std::min({m_min, m.mass[i], m.inertia[i] / r2});
  }
  return 2 * std::sqrt(m_min / (3 * s.materials[0].penalty * l / h));
}

// The numbers of docs/model.md: the smallest multiple of dt_crit (steps of 5%) at which
// each case goes unstable within 20,000 steps, and the former dt_crit in the same unit
// (run with --gtest_also_run_disabled_tests). The damped pile counts only blow-ups: it
// gains kinetic energy as it falls.
TEST(StepStabilityScan, DISABLED_ThresholdOverAcceptedStep) {
  struct Case {
    const char* name;
    Scene scene;
    bool energy;
  };
  for (Case c : {Case{"channel", test::channel_packing(), true},
                 Case{"hexagon", test::hexagon_packing(), true},
                 Case{"floor 0.1 mm", grain_on_thin_floor(1e-4), true},
                 Case{"floor 0.01 mm", grain_on_thin_floor(1e-5), true},
                 Case{"damped pile", test::jostling_pile(6, 4), false}}) {
    const double dt_crit = critical_step(c.scene);
    double threshold = 0;
    for (double f = 1.0; f < 40 && threshold == 0; f *= 1.05) {
      c.scene.simulation.dt = f * dt_crit;
      const Outcome o = run(c.scene, Backend::Cpu, 20000, true);
      if (o.blew_up || (c.energy && o.late > 10 * o.early)) threshold = f;
    }
    std::printf("%-14s dt_crit %.4g s, unstable from %.3g x dt_crit, former dt_crit %.3g x\n",
                c.name, dt_crit, threshold, former_critical_step(c.scene) / dt_crit);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
