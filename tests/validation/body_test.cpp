// Bodies of several triangles on the serial and OpenMP solvers: no contact inside a body,
// momentum of colliding bodies, free rotation with the exact inertia, OpenMP equal to
// serial bit for bit, the snapshot's body columns and checkpoints of bodies.
#include "core/initial_overlaps.hpp"
#include "core/particle_model.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"
#include "tridem/solver_state.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

constexpr const char* kHead =
    "[simulation]\nsteps = 1\ndt = 1e-6\n[[material]]\nname = \"m\"\ndensity = 2500\n"
    "penalty = 1e8\nfriction = 0.5\nrestitution = 0.5\n";

std::string ngon(int n, double radius, Vec2d c, Vec2d v, double w, double phase = 0) {
  std::string s = "[[body]]\nmaterial = \"m\"\npolygon = [";
  for (int k = 0; k < n; ++k) {
    const double t = phase + 2 * std::numbers::pi * k / n;
    s += fmt::format("{}[{:.17g}, {:.17g}]", k ? ", " : "", c.x + radius * std::cos(t),
                     c.y + radius * std::sin(t));
  }
  return s + fmt::format("]\nvelocity = [{}, {}]\nangular_velocity = {}\n", v.x, v.y, w);
}

// dt_crit bounds each body as one, but a regular polygon's triangulation has flat members
// on its outline, which stiffen its contacts: the bound is below the dt = 1e-6 these runs
// give, so they run with --force where they need it.
std::unique_ptr<Solver> solver_on(Scene scene, Backend b, bool force = false) {
  scene.simulation.backend = b;
  SolverConfig c;
  c.force = force;
  return make_solver(scene, c);
}

struct Momentum {
  Vec2d p{};
  double l = 0;  // about the origin
};

Momentum momentum(const Snapshot& s) {
  Momentum m;
  for (std::size_t i = 0; i < s.size(); ++i) {
    m.p += Vec2d{s.vx[i], s.vy[i]} * s.mass[i];
    m.l += s.mass[i] * cross(Vec2d{s.x[i], s.y[i]}, Vec2d{s.vx[i], s.vy[i]}) +
           s.inertia[i] * s.omega[i];
  }
  return m;
}

TEST(Bodies, FiftyMembersAtRestFeelNoContact) {
  const Scene scene = parse_scene(std::string(kHead) + ngon(52, 0.01, {0, 0}, {0, 0}, 0), "s");
  auto solver = solver_on(scene, Backend::Cpu, true);
  ASSERT_EQ(solver->size(), 50u);
  solver->advance(200);
  Snapshot s;
  solver->snapshot(s, true);
  EXPECT_TRUE(s.contacts.empty() || [&] {
    for (const auto& c : s.contacts)
      if (c.fx != 0 || c.fy != 0) return false;
    return true;
  }());
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(s.fx[i], 0.0) << i;
    EXPECT_EQ(s.fy[i], 0.0) << i;
    EXPECT_EQ(s.torque[i], 0.0) << i;
    EXPECT_EQ(s.vx[i], 0.0) << i;
    EXPECT_EQ(s.omega[i], 0.0) << i;
  }
}

Scene colliding_pair() {
  return parse_scene(std::string(kHead) + ngon(5, 0.01, {0, 0}, {0.5, 0.05}, 10) +
                         ngon(7, 0.012, {0.0235, 0.004}, {-0.4, 0}, -5, 0.3),
                     "s");
}

TEST(Bodies, CollidingBodiesConserveMomentum) {
  const Scene scene = colliding_pair();
  auto solver = solver_on(scene, Backend::Cpu);
  Snapshot s0, s1;
  solver->snapshot(s0, false);
  const Momentum before = momentum(s0);
  bool touched = false;
  for (int k = 0; k < 60; ++k) {
    solver->advance(100);
    solver->snapshot(s1, false);
    for (std::size_t i = 0; i < s1.size(); ++i) touched = touched || s1.fx[i] != 0;
  }
  ASSERT_TRUE(touched);
  const Momentum after = momentum(s1);
  // They changed direction: the collision happened and carried momentum across.
  EXPECT_NE(s1.vx[0], s0.vx[0]);
  const double scale = std::abs(before.p.x) + 1e-3;
  EXPECT_NEAR(after.p.x, before.p.x, 1e-12 * scale);
  EXPECT_NEAR(after.p.y, before.p.y, 1e-12 * scale);
  EXPECT_NEAR(after.l, before.l, 1e-10 * std::abs(before.l));
}

TEST(Bodies, OpenMPEqualsSerialBitForBit) {
  const Scene scene = colliding_pair();
  auto serial = solver_on(scene, Backend::Cpu);
  auto omp = solver_on(scene, Backend::OpenMP);
  serial->advance(4000);
  omp->advance(4000);
  Snapshot a, b;
  serial->snapshot(a, false);
  omp->snapshot(b, false);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.x[i], b.x[i]);
    EXPECT_EQ(a.y[i], b.y[i]);
    EXPECT_EQ(a.theta[i], b.theta[i]);
    EXPECT_EQ(a.vx[i], b.vx[i]);
    EXPECT_EQ(a.omega[i], b.omega[i]);
    EXPECT_EQ(a.fx[i], b.fx[i]);
  }
}

TEST(Bodies, FreeRotationKeepsAngularMomentumWithTheExactInertia) {
  const Scene scene =
      parse_scene(std::string(kHead) + ngon(9, 0.01, {0.3, -0.2}, {0.1, 0}, 40), "s");
  const ParticleModel model = build_particle_model(scene);
  const double l_body = model.bodies.inertia[0] * 40 +
                        model.bodies.mass[0] * cross(model.bodies.centroid[0], Vec2d{0.1, 0});
  auto solver = solver_on(scene, Backend::Cpu, true);
  Snapshot s;
  for (int k = 0; k < 5; ++k) {
    solver->advance(1000);
    solver->snapshot(s, false);
    // The members' angular momenta add up to the body's, I ω + M c × v, at every step.
    EXPECT_NEAR(momentum(s).l, l_body, 1e-12 * std::abs(l_body));
    EXPECT_EQ(s.omega[0], 40.0);
  }
  // The body turned: 5000 steps of 1 µs at 40 rad/s.
  EXPECT_NEAR(s.theta[0], 0.2, 1e-12);
}

// The snapshot's per-body columns (the contract outputs build on): ids, offsets, the
// model's mass and inertia, the pose of the body, and its load the sum of its members'.
TEST(Bodies, SnapshotShowsEachBody) {
  const Scene scene = colliding_pair();
  const ParticleModel model = build_particle_model(scene);
  auto solver = solver_on(scene, Backend::Cpu);
  Snapshot s;
  solver->snapshot(s, false);
  ASSERT_EQ(s.body_count(), 2u);
  ASSERT_EQ(s.member_body.size(), s.size());
  ASSERT_EQ(s.body_first.size(), 3u);
  EXPECT_EQ(s.body_first[0], 0);
  EXPECT_EQ(s.body_first[1], 3);  // a pentagon is 3 triangles
  EXPECT_EQ(s.body_first[2], static_cast<std::int64_t>(s.size()));
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(s.body_of(i), i < 3 ? 0 : 1) << i;
  }
  for (std::size_t b = 0; b < 2; ++b) {
    EXPECT_DOUBLE_EQ(s.body_mass[b], model.bodies.mass[b]);
    EXPECT_DOUBLE_EQ(s.body_inertia[b], model.bodies.inertia[b]);
    EXPECT_EQ(s.body_x[b], model.bodies.centroid[b].x);
    EXPECT_EQ(s.body_y[b], model.bodies.centroid[b].y);
  }
  EXPECT_EQ(s.body_vx[0], 0.5);
  EXPECT_EQ(s.body_omega[1], -5.0);
  bool touched = false;
  for (int k = 0; k < 60 && !touched; ++k) {
    solver->advance(100);
    solver->snapshot(s, false);
    touched = s.body_fx[0] != 0;
  }
  ASSERT_TRUE(touched);
  // Action and reaction between the two bodies; each body's force is its members'.
  EXPECT_NEAR(s.body_fx[0], -s.body_fx[1], 1e-9 * std::abs(s.body_fx[0]));
  for (std::size_t b = 0; b < 2; ++b) {
    double fx = 0, fy = 0;
    for (auto i = s.body_first[b]; i < s.body_first[b + 1]; ++i) {
      fx += s.fx[static_cast<std::size_t>(i)];
      fy += s.fy[static_cast<std::size_t>(i)];
    }
    EXPECT_EQ(s.body_fx[b], fx);
    EXPECT_EQ(s.body_fy[b], fy);
    // The members move with their body: the first member's angle is the body's.
    EXPECT_EQ(s.theta[static_cast<std::size_t>(s.body_first[b])], s.body_theta[b]);
  }
}

TEST(Bodies, SnapshotOfABodilessSceneHasNoBodyColumns) {
  // Appended, not `std::string(kHead) + "..."`: through the tests' precompiled header gcc 12
  // reports libstdc++'s operator+ as reading out of bounds (a known false -Warray-bounds).
  std::string text(kHead);
  text += "[[triangle]]\nmaterial = \"m\"\nvertices = [[0, 0], [0.01, 0], [0, 0.01]]\n";
  const Scene scene = parse_scene(text, "s");
  auto solver = solver_on(scene, Backend::Cpu);
  Snapshot s;
  solver->snapshot(s, false);
  EXPECT_TRUE(s.member_body.empty());
  EXPECT_TRUE(s.body_x.empty());
  EXPECT_TRUE(s.body_first.empty());
  EXPECT_EQ(s.body_count(), 1u);
  EXPECT_EQ(s.body_of(0), 0);
}

// A checkpoint of a body scene holds each body; a solver of another grouping refuses it.
TEST(Bodies, CheckpointHoldsTheBodies) {
  auto solver = solver_on(colliding_pair(), Backend::Cpu);
  solver->advance(10);
  SolverState state;
  solver->save_state(state);
  ASSERT_EQ(state.bodies(), 2u);
  Snapshot s;
  solver->snapshot(s, false);
  EXPECT_EQ(state.body_x, s.body_x);
  EXPECT_EQ(state.body_omega, s.body_omega);
  EXPECT_EQ(state.x, s.x);
  auto other = solver_on(
      parse_scene(std::string(kHead) + ngon(5, 0.01, {0, 0}, {0.5, 0.05}, 10), "s"), Backend::Cpu);
  try {
    other->load_state(state);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("for 3 particles"), std::string::npos) << e.what();
  }
  SolverState no_bodies = state;
  SolverState::for_each_body_column([&](auto field) { no_bodies.column(field).clear(); });
  try {
    solver->load_state(no_bodies);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("0 values of body x for 2 bodies"), std::string::npos)
        << e.what();
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// relax_overlaps moves a body as one: two heptagons placed 2 mm into each other and the
// first 1 mm into a fixed floor end apart and above the floor, each body translated by a
// single vector (its members keep their places relative to each other), the floor unmoved.
TEST(Bodies, RelaxOverlapsMovesEachBodyAsOne) {
  std::string text = std::string(kHead) + ngon(7, 0.01, {0, 0.009}, {0, 0}, 0) +
                     ngon(7, 0.01, {0.018, 0.009}, {0, 0}, 0, 0.2) +
                     "[[triangle]]\nmaterial = \"m\"\nfixed = true\n"
                     "vertices = [[-0.1, 0], [0.1, 0], [0, -0.05]]\n";
  text.insert(text.find("dt = 1e-6\n"), "relax_overlaps = true\n");
  Scene scene = parse_scene(text, "s");
  ASSERT_EQ(scene.bodies.size(), 3u);
  const Scene before = scene;
  const RelaxReport r = relax_initial_overlaps(scene);
  EXPECT_GE(r.pairs, 2u);
  EXPECT_FALSE(first_initial_overlap(scene.triangles).has_value());
  // Members of one body would overlap their neighbours if moved one by one: none did.
  for (std::size_t b = 0; b < 2; ++b) {
    const BodySpec& body = scene.bodies[b];
    const Vec2d move =
        scene.triangles[body.first].vertices[0] - before.triangles[body.first].vertices[0];
    EXPECT_GT(norm(move), 1e-4) << "body " << b;
    for (std::size_t i = body.first; i < body.first + body.count; ++i)
      for (int k = 0; k < 3; ++k) {
        const Vec2d d = scene.triangles[i].vertices[k] - before.triangles[i].vertices[k];
        EXPECT_NEAR(d.x, move.x, 1e-15) << "body " << b << " member " << i;
        EXPECT_NEAR(d.y, move.y, 1e-15) << "body " << b << " member " << i;
      }
  }
  const std::size_t floor = scene.triangles.size() - 1;
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(scene.triangles[floor].vertices[k].x, before.triangles[floor].vertices[k].x);
    EXPECT_EQ(scene.triangles[floor].vertices[k].y, before.triangles[floor].vertices[k].y);
  }
  for (std::size_t i = 0; i < floor; ++i)
    for (const Vec2d& v : scene.triangles[i].vertices) EXPECT_GE(v.y, -1e-9);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
