// relax_overlaps: overlapping triangles are pushed apart before the run by moving
// positions only, so the run starts with no energy it did not have. Without it, a grain
// placed 4 mm into a floor is shot off (the bug of issue 10, item 6).
#include "core/initial_overlaps.hpp"
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"
#include "tridem/output.hpp"
#include "tridem/run.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// An equilateral grain of edge 0.1 m standing `sink` metres into a fixed floor.
Scene grain_in_floor(double sink) {
  Scene s = test::empty_scene(1e7, 2000, 0.4, 0.2);
  s.simulation.gravity = {0, -9.81};
  s.triangles.push_back(test::floor_triangle(-1, 1));
  s.triangles.push_back(test::triangle({0, -sink}, {0.1, -sink}, {0.05, 0.0866 - sink}));
  return s;
}

double total_energy(Solver& solver, const Scene& s) {
  Snapshot snap;
  solver.snapshot(snap, false);
  return compute_energy(snap, s.simulation.gravity, solver.energy()).total();
}

double highest_kinetic(const Scene& s, int steps) {
  auto solver = test::solver_for(s, Backend::Cpu);
  Snapshot snap;
  double most = 0;
  for (int k = 0; k < steps; ++k) {
    solver->advance(1);
    solver->snapshot(snap, false);
    most = std::max(most, compute_energy(snap).kinetic);
  }
  return most;
}

TEST(RelaxOverlaps, GrainIntoTheFloorIsPushedOutByPositionsOnly) {
  Scene s = grain_in_floor(0.004);
  s.triangles[1].velocity = {0.25, 0};
  s.triangles[1].angular_velocity = 1;
  const Scene before = s;
  const RelaxReport r = relax_initial_overlaps(s);
  EXPECT_EQ(r.pairs, 1u);
  EXPECT_EQ(r.moved, 1u);
  EXPECT_EQ(r.first_moved, 1);
  EXPECT_NEAR(r.deepest, 0.004, 1e-12);
  EXPECT_NEAR(r.largest_move, 0.004, 1e-8);
  EXPECT_FALSE(first_initial_overlap(s.triangles));
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(s.triangles[0].vertices[k].x, before.triangles[0].vertices[k].x) << "floor stays";
    EXPECT_EQ(s.triangles[0].vertices[k].y, before.triangles[0].vertices[k].y) << "floor stays";
  }
  EXPECT_NEAR(s.triangles[1].vertices[0].y, 0, 1e-8) << "pushed up onto the floor";
  EXPECT_EQ(s.triangles[1].vertices[0].x, before.triangles[1].vertices[0].x);
  EXPECT_EQ(s.triangles[1].velocity.x, before.triangles[1].velocity.x);
  EXPECT_EQ(s.triangles[1].velocity.y, before.triangles[1].velocity.y);
  EXPECT_EQ(s.triangles[1].angular_velocity, before.triangles[1].angular_velocity);
}

TEST(RelaxOverlaps, RelaxedGrainStartsWithNoEnergyGain) {
  Scene relaxed = grain_in_floor(0.004);
  relax_initial_overlaps(relaxed);
  auto solver = test::solver_for(relaxed, Backend::Cpu);
  const double e0 = total_energy(*solver, relaxed);
  solver->advance(1);
  const double e1 = total_energy(*solver, relaxed);
  const double m = 2000 * 0.5 * 0.1 * 0.0866;
  // Energy after step 1 equals the energy before, to far less than the grain's weight
  // over a micrometre.
  EXPECT_NEAR(e1, e0, m * 9.81 * 1e-6);

  // Over 2000 steps the relaxed grain never moves faster than a free fall of a few
  // micrometres would make it; the sunk grain is shot off the floor.
  const double relaxed_peak = highest_kinetic(relaxed, 2000);
  const double sunk_peak = highest_kinetic(grain_in_floor(0.004), 2000);
  EXPECT_LT(relaxed_peak, m * 9.81 * 1e-5) << "relaxed";
  EXPECT_GT(sunk_peak, 1000 * relaxed_peak) << "energy from nothing without relaxation";
}

TEST(RelaxOverlaps, SeparatesADenseJumble) {
  Scene s = test::jostling_pile(12, 8);
  ASSERT_FALSE(find_initial_overlaps(s.triangles).empty()) << "the pile starts overlapping";
  const RelaxReport r = relax_initial_overlaps(s);
  EXPECT_GT(r.moved, 0u);
  EXPECT_TRUE(find_initial_overlaps(s.triangles).empty());
}

TEST(RelaxOverlaps, RunScenePushesApartAndSaysWhat) {
  test::TempDir dir;
  Scene s = grain_in_floor(0.004);
  s.simulation.relax_overlaps = true;
  s.simulation.steps = 20;
  s.simulation.backend = Backend::Cpu;
  s.output.dir = dir.path().string();
  const auto log = dir.path() / "log.txt";
  std::FILE* f = std::fopen(log.string().c_str(), "w");
  ASSERT_NE(f, nullptr);
  RunOptions o;
  o.progress = false;
  o.log = f;
  run_scene(s, o);
  std::fclose(f);
  const std::string text = test::read_file(log);
  EXPECT_NE(text.find("relax_overlaps: 1 overlapping pair (deepest 0.004 m) pushed apart in 1 "
                      "iteration: 1 particle moved (first id 1)"),
            std::string::npos)
      << text;
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
