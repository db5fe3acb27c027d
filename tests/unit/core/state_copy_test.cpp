// The live view's StateCopy (tridem/state_copy.hpp) on every backend: what finish() hands
// over is the snapshot and the energy budget of the step at which start() was called, to
// the bit, though the solver has gone on stepping in between; the copy is reused; and the
// snapshot fallback agrees with it.
#include "support/backend_test.hpp"
#include "support/body_scenes.hpp"
#include "support/bonded_disc.hpp"
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::BackendTest;

void expect_same_budget(const EnergyBudget& got, const EnergyBudget& want) {
  EXPECT_EQ(got.elastic, want.elastic);
  EXPECT_EQ(got.dissipated_damping, want.dissipated_damping);
  EXPECT_EQ(got.dissipated_friction, want.dissipated_friction);
  EXPECT_EQ(got.dissipated_local, want.dissipated_local);
  EXPECT_EQ(got.dissipated_fracture, want.dissipated_fracture);
  EXPECT_EQ(got.wall_work, want.wall_work);
}

/// The copy of `copy` started now holds what a snapshot and energy() say now, though the
/// solver advances `later` steps before finish().
void expect_copy_of_this_step(Solver& solver, StateCopy& copy, std::int64_t later) {
  Snapshot want;
  solver.snapshot(want, false);
  const EnergyBudget budget = solver.energy();
  copy.start();
  solver.advance(later);
  Snapshot got;
  const EnergyBudget got_budget = copy.finish(got);
  EXPECT_EQ(got.step, want.step);
  EXPECT_EQ(got.time, want.time);
  Snapshot::for_each_field([&](auto field) {
    for_each_array(got.column(field), [&](const std::vector<double>& values, int k) {
      EXPECT_EQ(values, array_at(want.column(field), k)) << decltype(field)::name << " " << k;
    });
  });
  EXPECT_EQ(got.bond_damage, want.bond_damage);
  expect_same_budget(got_budget, budget);
}

class StateCopyTest : public BackendTest {
 protected:
  void check_scene(const Scene& scene, std::int64_t before) {
    auto solver = test::solver_for(scene, GetParam());
    const std::unique_ptr<StateCopy> copy = solver->make_state_copy();
    // Step 0 (no pair results yet), then after `before` steps, twice with one copy.
    expect_copy_of_this_step(*solver, *copy, 3);
    solver->advance(before);
    expect_copy_of_this_step(*solver, *copy, 5);
    expect_copy_of_this_step(*solver, *copy, 1);
  }
};

TEST_P(StateCopyTest, IsTheSnapshotAndEnergyOfItsStep) {
  check_scene(test::jostling_pile(6, 4), 40);
}

TEST_P(StateCopyTest, CarriesBodiesAndTheirWalls) { check_scene(test::colliding_bodies(), 60); }

TEST_P(StateCopyTest, CarriesTheBondsDamageAndEnergy) {
  Scene scene;
  try {
    scene = test::loaded_bonded_disc();
  } catch (const SceneError& e) {
    GTEST_SKIP() << "no Gmsh to mesh the disc: " << e.what();
  }
  check_scene(scene, test::kLoadedDiscDamagedBy);
}

TRIDEM_INSTANTIATE_SOLVERS(StateCopyTest);

TEST(StateCopy, SnapshotFallbackIsTheSnapshotToo) {
  Scene scene = test::jostling_pile(6, 4);
  scene.simulation.backend = Backend::Cpu;
  auto solver = make_solver(scene, {});
  const std::unique_ptr<StateCopy> copy = make_snapshot_copy(*solver);
  solver->advance(30);
  expect_copy_of_this_step(*solver, *copy, 4);
  expect_copy_of_this_step(*solver, *copy, 2);
}

// A solver numbering the particles by place (core/place_numbered_solver) gives the live
// view the state in the scene's ids, as its snapshots.
TEST(StateCopy, OfASolverNumberingByPlaceIsItsSnapshot) {
  Scene scene = test::jostling_pile(6, 4);
  scene.simulation.backend = Backend::Cpu;
  SolverConfig config;
  config.particle_order = ParticleOrder::Place;
  auto solver = make_solver(scene, config);
  ASSERT_NE(solver->description().find("numbered by place"), std::string::npos);
  const std::unique_ptr<StateCopy> copy = solver->make_state_copy();
  solver->advance(30);
  expect_copy_of_this_step(*solver, *copy, 4);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
