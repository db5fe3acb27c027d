// A run's final.csv read back as a scene ([[import]]) reproduces the state it holds:
// every triangle's vertices and centroid, velocity and angular velocity, in id order.
// (The orientation restarts at theta = 0 about the vertices as read, and contact history
// is not in final.csv: a checkpoint is the exact restart.)
#include "tridem/output.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"

#include "unit/io/io_test_support.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

constexpr const char* kScene =
    "[simulation]\nsteps = 1\ndt = 2e-5\n[[material]]\nname = \"m\"\ndensity = 2500\n"
    "penalty = 1e7\nfriction = 0.4\nrestitution = 0.5\n"
    "[[triangle]]\nmaterial = \"m\"\nvertices = [[0, 0], [1, 0], [0.5, 0.8]]\nvelocity = [1, 0]\n"
    "angular_velocity = 2\n"
    "[[triangle]]\nmaterial = \"m\"\nvertices = [[1.05, 0], [2, 0], [1.6, 0.9]]\nvelocity = [-1, "
    "0.5]\n"
    "[[generate]]\nkind = \"triangles\"\nmaterial = \"m\"\nregion = [[0, 1.5], [2, 3]]\n"
    "size = [0.2, 0.4]\ncount = 12\nseed = 4\nvelocity = [0, -2]\n";

Snapshot state_of(const Solver& s) {
  Snapshot snap;
  s.snapshot(snap, false);
  return snap;
}

TEST(FinalCsvRoundTrip, ReadingFinalCsvBackReproducesTheState) {
  Scene scene = parse_scene(kScene, "roundtrip.toml");
  scene.simulation.backend = Backend::Cpu;
  const auto solver = make_solver(scene, SolverConfig{});
  solver->advance(2000);  // long enough for the first two to collide and turn
  const Snapshot before = state_of(*solver);
  ASSERT_GT(before.omega[1] * before.omega[1], 0);  // the collision turned the second one

  const test::TempDir temp;  // its own folder: other runs of the suite may run beside it
  const auto& dir = temp.path();
  write_final_csv(dir / "final.csv", before);
  Scene again = parse_scene(
      "[simulation]\nsteps = 1\ndt = 2e-5\n[[material]]\nname = \"m\"\ndensity = 2500\n"
      "penalty = 1e7\nfriction = 0.4\nrestitution = 0.5\n[[import]]\nfile = \"final.csv\"\n"
      "material = \"m\"\nkeep_overlaps = true\n",  // the contacts' overlaps are the state
      (dir / "again.toml").string());
  again.simulation.backend = Backend::Cpu;
  const Snapshot after = state_of(*make_solver(again, SolverConfig{}));

  ASSERT_EQ(after.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    SCOPED_TRACE(fmt::format("particle {}", i));
    // Written with 17 digits: the velocities come back bit for bit; the vertices are
    // placed again from the centroid and offsets the model computes from them, so they
    // agree to rounding, as does the centroid.
    EXPECT_EQ(after.vx[i], before.vx[i]);
    EXPECT_EQ(after.vy[i], before.vy[i]);
    EXPECT_EQ(after.omega[i], before.omega[i]);
    for (const auto member : {&Snapshot::x1, &Snapshot::y1, &Snapshot::x2, &Snapshot::y2,
                              &Snapshot::x3, &Snapshot::y3, &Snapshot::x, &Snapshot::y})
      EXPECT_NEAR((after.*member)[i], (before.*member)[i], 1e-14);
    EXPECT_EQ(after.theta[i], 0);
    EXPECT_DOUBLE_EQ(after.mass[i], before.mass[i]);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
