// The notched beam of issue 14 (docs/fracture.md, "The notched beam"): a mode I crack grown
// from a notch's tip through the ligament of a beam in three-point bending releases G_I
// times its length within 20%, and its bonds fail mostly in opening. The beam is loaded to
// full fracture: until the crack's projection covers the ligament and the nose's load has
// fallen to a small part of its peak.
#include "support/notched_beam.hpp"
#include "tridem/error.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"
#include "tridem/solver_state.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// What a run of the beam to full fracture gives.
struct BeamRun {
  test::CrackMeasure crack;
  double fracture = 0;  ///< J/m: energy.csv's dissipated_fracture (bonds.csv's fracture_energy)
  double g1 = 0;        ///< G_I of the beam
  std::int64_t steps = 0;
  bool settled = false;  ///< the crack stopped growing before the step limit
};

// Loads `beam` until the crack has reached the top face (to within an element: its last
// bond is the hinge the halves turn about) and released nothing more for 4000 steps, and
// prints what it measured: the crack, its energy, and each bond with a broken point.
BeamRun run_to_full_fracture(const test::NotchedBeam& beam, const Scene& scene) {
  auto solver = make_solver(scene, SolverConfig{});
  Snapshot snap;
  SolverState state;
  BeamRun run;
  run.g1 = scene.materials[0].fracture_energy;
  test::CrackMeasure& crack = run.crack;
  double peak = 0, force = 0, settled_from = 0;
  const std::int64_t chunk = 500, quiet = 4000, limit = 40000;
  std::int64_t quiet_since = 0;
  while (solver->step() < limit) {
    solver->advance(chunk);
    solver->snapshot(snap, false);
    solver->save_state(state);
    force = snap.fy[2];  // the beam pushes the nose up
    peak = std::max(peak, force);
    crack = test::measure_crack(scene, state, beam, beam.depth / 3);
    if (crack.total_energy > settled_from * (1 + 1e-4)) {
      settled_from = crack.total_energy;
      quiet_since = solver->step();
    }
    if (crack.projected >= crack.ligament - beam.size && solver->step() - quiet_since >= quiet) {
      run.settled = true;
      break;
    }
  }
  run.steps = solver->step();
  run.fracture = solver->energy().dissipated_fracture;
  const double path = run.g1 * crack.path_length, projected = run.g1 * crack.projected;
  std::printf(
      "notched beam, mesh %g m, nose at %g m/s: %zu triangles, %zu bonds, %lld steps (t = %.3g "
      "s), peak load %.4g N/m, load at the end %.3g N/m\n"
      "crack: %d bonds (%d broken), path %.4g mm, projected %.4g of the ligament's %.4g mm, "
      "tortuosity %.3f, mean |angle| %.1f deg; %d bonds broken elsewhere, %d damaged\n"
      "energy: %.4g J/m = crack %.4g + elsewhere %.4g + damaged %.4g; G_I x path %.4g (ratio "
      "%.3f), G_I x projected %.4g (ratio %.3f); sum of G(theta) L/2 on the crack %.4g; "
      "mode II share %.3f\n",
      beam.size, beam.speed, scene.triangles.size() - 3, scene.bonds.size(),
      static_cast<long long>(run.steps), snap.time, peak, force, crack.crack_bonds,
      crack.broken_bonds, crack.path_length * 1e3, crack.projected * 1e3, crack.ligament * 1e3,
      crack.tortuosity(), crack.mean_abs_angle, crack.other_bonds, crack.damaged_bonds,
      run.fracture, crack.crack_energy, crack.other_energy, crack.damaged_energy, path,
      run.fracture / path, projected, run.fracture / projected, crack.predicted_energy,
      crack.mode2_share);
  for (std::size_t k = 0; k < scene.bonds.size(); ++k) {
    const double d0 = state.bond_damage[2 * k], d1 = state.bond_damage[2 * k + 1];
    const BondSpec& b = scene.bonds[k];
    if (d0 == 1 || d1 == 1)
      std::printf("  bond %zu: (%.2f, %.2f)-(%.2f, %.2f) mm, damage %.3f %.3f, %.4g J/m = %.3f "
                  "G_I L\n",
                  k, b.p.x * 1e3, b.p.y * 1e3, b.q.x * 1e3, b.q.y * 1e3, d0, d1,
                  state.bond_dissipated[k], state.bond_dissipated[k] / (run.g1 * norm(b.q - b.p)));
  }
  return run;
}

TEST(NotchedBeam, FractureEnergyIsGITimesTheCrackLength) {
  const test::NotchedBeam beam;
  Scene scene;
  try {
    scene = test::notched_beam_scene(beam);
  } catch (const SceneError& e) {
    GTEST_SKIP() << e.what();  // a build without Gmsh
  }
  const BeamRun run = run_to_full_fracture(beam, scene);
  const test::CrackMeasure& crack = run.crack;
  const double path = run.g1 * crack.path_length, projected = run.g1 * crack.projected;
  RecordProperty("fracture_over_gi_path", std::to_string(run.fracture / path));
  RecordProperty("fracture_over_gi_projected", std::to_string(run.fracture / projected));
  RecordProperty("tortuosity", std::to_string(crack.tortuosity()));
  ASSERT_GE(crack.projected, crack.ligament - beam.size) << "the crack must cut the ligament";
  EXPECT_TRUE(run.settled) << "the crack must stop growing";
  EXPECT_NEAR(crack.total_energy, run.fracture, 1e-9 * run.fracture);
  // The check: the energy released is G_I times the crack's length within 20%, the
  // length of its faces (the broken edges), on which G_I is defined.
  EXPECT_NEAR(run.fracture, path, 0.2 * path);
  // Mode I: the crack's bonds failed mostly in opening.
  EXPECT_LT(crack.mode2_share, 0.2);
  // The crack follows the mesh's edges, longer than its projection on the ligament: the
  // energy per unit of ligament exceeds G_I by about the tortuosity.
  EXPECT_GT(run.fracture, projected);
}

// The numbers of docs/fracture.md's other columns: the beam loaded half as fast, and meshed
// at 1 mm (about 8 minutes on the shared 2-core machine at a load of 8).
TEST(NotchedBeam, DISABLED_MeshAndRateStudy) {
  test::NotchedBeam slow, fine;
  slow.speed = 0.1;
  fine.size = 0.001;
  for (const test::NotchedBeam& beam : {slow, fine}) {
    Scene scene;
    try {
      scene = test::notched_beam_scene(beam);
    } catch (const SceneError& e) {
      GTEST_SKIP() << e.what();
    }
    const BeamRun run = run_to_full_fracture(beam, scene);
    EXPECT_TRUE(run.settled);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
