// Cohesive bonds in the CPU solvers (issue 14; docs/fracture.md): two bonded triangles
// ring without breaking and conserve energy, a fast separation breaks the bond and
// dissipates G_I times the edge, an intact bond suppresses the pair's contact, OpenMP
// equals serial bit for bit on a breaking disc, a checkpoint's state continues the run
// exactly, the solver's bond loads are the shared rules' (physics/bond_step.hpp, which the
// CUDA kernels call too), the parity tests' loaded disc is damaged within their steps, and
// the CUDA backend runs a bonded scene, or says why not where there is no GPU.
#include "backends/cuda/cuda_backend.hpp"
#include "core/bond_columns.hpp"
#include "core/particle_model.hpp"
#include "physics/bond_step.hpp"
#include "physics/local_frame.hpp"
#include "support/bonded_disc.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"
#include "tridem/solver_state.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// Two right triangles of legs 1 cm forming a square, bonded along its diagonal; b moves
// away from a along the diagonal's normal at `speed` (each side half of it).
Scene bonded_square(double speed) {
  Scene s;
  s.source = "bonded square";
  s.materials = {test::granite()};
  const double l = 0.01;
  TriangleSpec a, b;
  a.vertices = {Vec2d{0, 0}, Vec2d{l, 0}, Vec2d{l, l}};  // below the diagonal
  b.vertices = {Vec2d{0, 0}, Vec2d{l, l}, Vec2d{0, l}};  // above
  const Vec2d n{-std::sqrt(0.5), std::sqrt(0.5)};        // from a to b
  a.velocity = n * (-0.5 * speed);
  b.velocity = n * (0.5 * speed);
  s.triangles = {a, b};
  s.bonds = {BondSpec{0, 1, Vec2d{0, 0}, Vec2d{l, l}}};
  s.simulation.steps = 1;
  s.simulation.safety = 0.2;
  s.simulation.backend = Backend::Cpu;
  return s;
}

double kinetic(const Snapshot& s) {
  double e = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    e += 0.5 * s.mass[i] * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]) +
         0.5 * s.inertia[i] * s.omega[i] * s.omega[i];
  return e;
}

TEST(Bonds, SlowSeparationRingsAndKeepsItsEnergy) {
  // The bond's peak stores f_t^2 / (2k) * L; start with a tenth of it as kinetic energy.
  const double l = 0.01 * std::sqrt(2.0);
  const double h = 0.01 * std::sqrt(2.0) / 3;  // centroids' distance across the diagonal
  const double k = 40e9 / h;
  const double peak_energy = 8e6 * 8e6 / (2 * k) * l;
  const double mass = 2650 * 0.5e-4;
  const double speed = std::sqrt(2 * 0.1 * peak_energy / (0.5 * mass));  // relative speed
  Scene scene = bonded_square(speed);
  // A small step: symplectic Euler's energy wobbles by about omega dt / 2.
  scene.simulation.safety = 0.02;
  auto solver = make_solver(scene, SolverConfig{});
  Snapshot snap;
  solver->snapshot(snap, false);
  const double e0 = kinetic(snap);
  double lowest_kinetic = e0;
  for (int i = 0; i < 400; ++i) {
    solver->advance(5);
    solver->snapshot(snap, false);
    const EnergyBudget b = solver->energy();
    EXPECT_EQ(b.dissipated_fracture, 0.0);
    EXPECT_EQ(b.dissipated_friction, 0.0);  // no contact force inside an intact bond
    EXPECT_NEAR(kinetic(snap) + b.elastic, e0, 0.05 * e0) << "step " << solver->step();
    lowest_kinetic = std::min(lowest_kinetic, kinetic(snap));
  }
  // It turned round: the bond took (almost) all of the kinetic energy at some point.
  EXPECT_LT(lowest_kinetic, 0.1 * e0);
  // And they are still together: the gap stays below the elastic limit's.
  EXPECT_LT(std::abs(snap.y[1] - snap.y[0] - 0.01 / 3), 1e-3 * 0.01);
}

TEST(Bonds, FastSeparationBreaksAndReleasesTheFractureEnergy) {
  const double l = 0.01 * std::sqrt(2.0);
  const double g = 30 * l;            // G_I times the edge, J/m
  const double mass = 2650 * 0.5e-4;  // each triangle
  // Kinetic energy 3 G_I L (reduced mass m/2): the bond breaks and they fly apart.
  const double speed = std::sqrt(2 * 3 * g / (0.5 * mass));
  Scene scene = bonded_square(speed);
  scene.simulation.safety = 0.02;
  auto solver = make_solver(scene, SolverConfig{});
  solver->advance(4000);
  const EnergyBudget b = solver->energy();
  SolverState state;
  solver->save_state(state);
  ASSERT_EQ(state.bond_damage.size(), 2u);
  EXPECT_EQ(state.bond_damage[0], 1.0);
  EXPECT_EQ(state.bond_damage[1], 1.0);
  EXPECT_EQ(b.elastic, 0.0);
  // Mode I: the released energy is G_I per unit length of the edge (the law books it
  // exactly, whatever the step).
  EXPECT_NEAR(b.dissipated_fracture, g, 1e-6 * g);
  // Energy: what the bond released is what the pair's kinetic energy lost.
  Snapshot snap;
  solver->snapshot(snap, false);
  const double e0 = 0.5 * (0.5 * mass) * speed * speed;
  EXPECT_NEAR(kinetic(snap) + b.dissipated_fracture, e0, 0.01 * e0);
}

TEST(Bonds, OpenMPEqualsSerialOnABreakingDisc) {
  const std::string toml =
      "[simulation]\nsteps = 1\nsafety = 0.2\nbackend = \"cpu\"\n"
      "[[material]]\nname = \"g\"\ndensity = 2650\npenalty = 5e10\nfriction = 0.6\n"
      "young_modulus = 40e9\ntensile_strength = 8e6\nshear_strength = 25e6\n"
      "friction_angle = 35\nfracture_energy = 30\nshear_fracture_energy = 150\n"
      "[[mesh]]\nkind = \"disc\"\ncenter = [0, 0]\nradius = 0.01\nsize = 0.002\n"
      "material = \"g\"\nbonded = true\n";
  Scene scene;
  try {
    scene = parse_scene(toml, "disc.toml");
  } catch (const SceneError& e) {
    GTEST_SKIP() << e.what();  // a build without Gmsh
  }
  // Spin it fast enough to tear the rim off: bonds break while OpenMP runs (from step
  // 400 or so; 60 of 293 broken at step 500).
  for (TriangleSpec& t : scene.triangles) {
    const Vec2d c = (t.vertices[0] + t.vertices[1] + t.vertices[2]) / 3.0;
    t.velocity = Vec2d{-c.y, c.x} * 20000.0;
    t.angular_velocity = 20000;
  }
  SolverConfig serial_config;
  auto serial = make_solver(scene, serial_config);
  scene.simulation.backend = Backend::OpenMP;
  SolverConfig parallel_config;
  parallel_config.threads = 2;
  auto parallel = make_solver(scene, parallel_config);
  serial->advance(500);
  parallel->advance(500);
  Snapshot a, b;
  serial->snapshot(a, true);
  parallel->snapshot(b, true);
  test::expect_identical(a, b);
  const EnergyBudget ea = serial->energy(), eb = parallel->energy();
  EXPECT_GT(ea.dissipated_fracture, 0.0) << "the test must break bonds";
  EXPECT_EQ(ea.dissipated_fracture, eb.dissipated_fracture);
  EXPECT_EQ(ea.elastic, eb.elastic);
  SolverState sa, sb;
  serial->save_state(sa);
  parallel->save_state(sb);
  EXPECT_EQ(sa.bond_damage, sb.bond_damage);
  std::size_t broken = 0;
  for (std::size_t k = 0; k < sa.bonds(); ++k)
    broken += sa.bond_damage[2 * k] == 1 && sa.bond_damage[2 * k + 1] == 1;
  EXPECT_GT(broken, 0u);
  EXPECT_LT(broken, sa.bonds());

  // A checkpoint's state continues the run bit for bit.
  auto restarted = make_solver(scene, parallel_config);
  restarted->load_state(sb);
  restarted->advance(100);
  parallel->advance(100);
  Snapshot c, d;
  restarted->snapshot(c, false);
  parallel->snapshot(d, false);
  test::expect_identical(c, d);
  EXPECT_EQ(restarted->energy().dissipated_fracture, parallel->energy().dissipated_fracture);
}

TEST(Bonds, StateOfAnotherScenesBondsIsRefused) {
  auto solver = make_solver(bonded_square(0), SolverConfig{});
  SolverState state;
  solver->save_state(state);
  state.bond_damage.clear();
  state.bond_dissipated.clear();
  EXPECT_THROW(solver->load_state(state), Error);
  solver->save_state(state);
  state.bond_damage[0] = 1.5;
  EXPECT_THROW(solver->load_state(state), Error);
}

// Steps `scene` one step at a time until a bond breaks (or `max_steps`), checking that the
// solver's loads are exactly what the shared rules give from the state before the step:
// step_bond for each bond's force, add_bond_loads for each triangle's sum (no contact acts:
// an intact bond suppresses its pair's, and the scenes' other pairs never overlap), and
// commit_bond for the damage the step leaves. Returns the steps at which some point was
// softening (damaged, not broken).
int expect_solver_loads_are_the_shared_rules(const Scene& scene, int max_steps) {
  const ParticleModel model = build_particle_model(scene);
  HostBondColumns<double> bonds = initial_bond_columns<double>(build_bond_model(scene, model));
  const physics::BondArrays<double> v = bonds.view(bonds.size());
  auto solver = make_solver(scene, SolverConfig{});
  Snapshot before, after;
  SolverState state, next;
  int softening = 0;
  auto any_broken = [&] {
    return std::any_of(bonds.broken.begin(), bonds.broken.end(), [](auto b) { return b != 0; });
  };
  for (int step = 0; step < max_steps && !any_broken(); ++step) {
    solver->snapshot(before, false);
    solver->save_state(state);
    for (std::size_t p = 0; p < bonds.damage.size(); ++p) bonds.damage[p] = state.bond_damage[p];
    solver->advance(1);
    solver->snapshot(after, false);
    double elastic = 0;
    for (std::int64_t k = 0; k < v.count; ++k) {
      const Vec2d origin{before.x[v.a[k]], before.y[v.a[k]]};
      v.result[k] = physics::step_bond(
          v, k, physics::offset_from<double>(origin, Vec2d{before.x[v.b[k]], before.y[v.b[k]]}),
          before.theta[v.a[k]], before.theta[v.b[k]]);
      elastic += v.result[k].elastic;
    }
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(after.size()); ++i) {
      Vec2d f{};
      double t = 0;
      physics::add_bond_loads(v, i, f, t);
      EXPECT_EQ(after.fx[i], f.x) << "step " << step << ", triangle " << i;
      EXPECT_EQ(after.fy[i], f.y) << "step " << step << ", triangle " << i;
      EXPECT_EQ(after.torque[i], t) << "step " << step << ", triangle " << i;
    }
    for (std::int64_t k = 0; k < v.count; ++k) physics::commit_bond(v, k);
    solver->save_state(next);
    EXPECT_EQ(next.bond_damage, bonds.damage) << "step " << step;
    EXPECT_EQ(next.bond_dissipated, bonds.dissipated) << "step " << step;
    EXPECT_EQ(solver->energy().elastic, elastic) << "step " << step;
    if (::testing::Test::HasFailure()) return softening;
    softening += std::any_of(bonds.damage.begin(), bonds.damage.end(),
                             [](double d) { return d > 0 && d < 1; });
  }
  EXPECT_TRUE(any_broken()) << "a bond must break within " << max_steps << " steps";
  return softening;
}

// A bonded pair whose bond softens and slides.
TEST(Bonds, SolverLoadsAreTheSharedRules) {
  const double l = 0.01 * std::sqrt(2.0);
  const double g = 30 * l, mass = 2650 * 0.5e-4;
  // Separating at the speed that breaks it, and sliding and turning: both modes soften.
  Scene scene = bonded_square(std::sqrt(2 * 3 * g / (0.5 * mass)));
  scene.triangles[1].velocity += Vec2d{0.5, 0.5};
  scene.triangles[1].angular_velocity = 20;
  scene.simulation.safety = 0.02;
  EXPECT_GT(expect_solver_loads_are_the_shared_rules(scene, 3000), 10)
      << "the bond must soften over several steps";
}

// A strip of two bonded squares, four triangles and three bonds (two triangles hold two
// bonds each: their loads are summed in bond order), stretched along its length and
// sheared until a bond breaks.
TEST(Bonds, SolverLoadsAreTheSharedRulesOnAStrip) {
  const double l = 0.01;
  Scene s;
  s.source = "bonded strip";
  s.materials = {test::granite()};
  TriangleSpec t;
  t.vertices = {Vec2d{0, 0}, Vec2d{l, 0}, Vec2d{l, l}};  // 0: the left square's lower half
  s.triangles.push_back(t);
  t.vertices = {Vec2d{0, 0}, Vec2d{l, l}, Vec2d{0, l}};  // 1: its upper half
  s.triangles.push_back(t);
  t.vertices = {Vec2d{l, 0}, Vec2d{2 * l, 0}, Vec2d{2 * l, l}};  // 2: the right one's lower
  s.triangles.push_back(t);
  t.vertices = {Vec2d{l, 0}, Vec2d{2 * l, l}, Vec2d{l, l}};  // 3: its upper half
  s.triangles.push_back(t);
  s.bonds = {BondSpec{0, 1, Vec2d{0, 0}, Vec2d{l, l}}, BondSpec{0, 3, Vec2d{l, 0}, Vec2d{l, l}},
             BondSpec{2, 3, Vec2d{l, 0}, Vec2d{2 * l, l}}};
  // Stretched at 11 m/s between its outer triangles, sheared and turned a little. Each triangle
  // shrunk by 2 % about its centroid, so that those sharing a vertex do not touch (a vertex contact
  // has a force of its own); the bonds' points are on the edges about the centroids, which
  // the shrinking leaves in place.
  for (TriangleSpec& tri : s.triangles) {
    const Vec2d c = (tri.vertices[0] + tri.vertices[1] + tri.vertices[2]) / 3.0;
    for (Vec2d& vertex : tri.vertices) vertex = c + (vertex - c) * 0.98;
    tri.velocity = Vec2d{(c.x - l) * 800, (c.x - l) * 100};
    tri.angular_velocity = 5;
  }
  s.simulation.steps = 1;
  s.simulation.safety = 0.05;
  s.simulation.backend = Backend::Cpu;
  EXPECT_GT(expect_solver_loads_are_the_shared_rules(s, 20000), 10)
      << "the bonds must soften over several steps";
}

// The parity and restart tests' specimen (support/bonded_disc.hpp) is damaged by the
// checkpoint of the restart test and has broken bonds, and intact ones, by the end of the
// parity test: otherwise those tests would compare intact bonds only.
TEST(Bonds, LoadedDiscIsDamagedWithinTheParitySteps) {
  Scene scene;
  try {
    scene = test::loaded_bonded_disc();
  } catch (const SceneError& e) {
    GTEST_SKIP() << e.what();  // a build without Gmsh
  }
  auto solver = make_solver(scene, SolverConfig{});
  SolverState state;
  solver->advance(test::kLoadedDiscDamagedBy);
  solver->save_state(state);
  const test::BondCount half = test::count_bonds(state);
  solver->advance(test::kLoadedDiscSteps - test::kLoadedDiscDamagedBy);
  solver->save_state(state);
  const test::BondCount end = test::count_bonds(state);
  std::printf("loaded disc: %zu triangles, %zu bonds; step %lld: %zu damaged, %zu broken; step "
              "%lld: %zu damaged, %zu broken\n",
              solver->size(), state.bonds(), static_cast<long long>(test::kLoadedDiscDamagedBy),
              half.damaged, half.broken, static_cast<long long>(test::kLoadedDiscSteps),
              end.damaged, end.broken);
  EXPECT_GT(half.damaged, 0u);
  EXPECT_GT(end.broken, half.broken);
  EXPECT_LT(end.broken, state.bonds());
}

// The GPU computes bonds (issue 14): a bonded scene runs on backend cuda where a GPU is
// usable; without one, the request is refused with the reason and the way out, as for any
// scene, and auto runs it on the CPU.
TEST(Bonds, CudaRunsABondedSceneOrSaysWhyNot) {
  Scene scene = bonded_square(0);
  scene.simulation.backend = Backend::Cuda;
  std::string why;
  if (cuda_available(&why)) {
    auto solver = make_solver(scene, SolverConfig{});
    EXPECT_NE(solver->description().find("cuda"), std::string::npos) << solver->description();
    solver->advance(10);
    SolverState state;
    solver->save_state(state);
    EXPECT_EQ(state.bonds(), 1u);
  } else {
    try {
      make_solver(scene, SolverConfig{});
      FAIL() << "backend cuda ran without a GPU";
    } catch (const RunError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("not available"), std::string::npos) << m;
      EXPECT_NE(m.find(why), std::string::npos) << m;
      EXPECT_EQ(m.find("cohesive bonds"), std::string::npos) << "bonds are no reason: " << m;
    }
    scene.simulation.backend = Backend::Auto;
    auto solver = make_solver(scene, SolverConfig{});
    EXPECT_EQ(solver->description().find("cuda"), std::string::npos) << solver->description();
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
