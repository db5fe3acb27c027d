// The CPU solvers' kept pair list (CpuSolver::kept_pair_list): on the grid without a
// periodic cell, a scene's skin makes the list from boxes grown by it and keeps it until a
// box leaves its grown copy. That must change nothing but the speed: the same bits as a list
// built every step from the boxes themselves (skin 0), for the serial and OpenMP solvers in
// both precisions, with moving walls, bodies and bonds; and the list must indeed be kept.
#include "backends/cpu/cpu_solver.hpp"
#include "support/body_scenes.hpp"
#include "support/bonded_specimens.hpp"
#include "support/program_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"

#include <gtest/gtest.h>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

struct KeptListCase {
  const char* name;
  Scene (*scene)();
  std::int64_t steps;
  double skin;          ///< small where the grains move slowly, so that the list is built again
  bool breaks = false;  ///< bonds break (fracture dissipates energy) while the list is kept
};

Scene pile() { return test::jostling_pile(20, 12); }
Scene walls() { return test::programmed_pile(12, 8); }
Scene bodies() { return test::settling_body_pile(300); }
Scene bonded() { return test::compression_scene(0.1, 0.2, 0.02, 5.0); }

const KeptListCase kCases[] = {{"JostlingPile", pile, 400, 0.05},
                               {"ProgrammedWalls", walls, 400, 0.05},
                               {"Bodies", bodies, 300, 0.005},
                               {"Bonds", bonded, 300, 0.005, true}};

struct Run {
  Snapshot snapshot;
  EnergyBudget energy;
  std::int64_t list_builds = -1;  ///< the kept list's builds; -1 on a list built every step
  std::string statistics;
};

template <class Real>
Run run(Scene s, Backend backend, double skin, std::int64_t steps) {
  s.simulation.skin = skin;
  const auto solver = test::advanced_solver(
      s, backend, steps, sizeof(Real) == 8 ? Precision::Double : Precision::Float);
  Run r;
  solver->snapshot(r.snapshot, true);
  r.energy = solver->energy();
  r.statistics = solver->statistics();
  if (const auto* cpu = dynamic_cast<const CpuSolver<Real>*>(solver.get()); cpu && skin > 0)
    r.list_builds = cpu->list_builds();
  return r;
}

template <class Real>
void expect_kept_list_is_exact(const KeptListCase& c, Backend backend) {
  const Scene s = c.scene();
  const Run every = run<Real>(s, backend, 0, c.steps);
  const Run kept = run<Real>(s, backend, c.skin, c.steps);
  test::expect_identical(every.snapshot, kept.snapshot);
  EXPECT_TRUE(test::same_bits(every.energy.elastic, kept.energy.elastic));
  EXPECT_TRUE(test::same_bits(every.energy.dissipated_friction, kept.energy.dissipated_friction));
  EXPECT_TRUE(test::same_bits(every.energy.dissipated_damping, kept.energy.dissipated_damping));
  EXPECT_TRUE(test::same_bits(every.energy.wall_work, kept.energy.wall_work));
  EXPECT_TRUE(test::same_bits(every.energy.dissipated_fracture, kept.energy.dissipated_fracture));
  EXPECT_GT(every.snapshot.contacts.size(), 10u) << "the scene's grains touch";
  if (c.breaks) {
    EXPECT_GT(kept.energy.dissipated_fracture, 0);
  }
  EXPECT_GT(kept.list_builds, 1) << "the list is built again as grains move";
  EXPECT_LT(kept.list_builds, c.steps / 2) << "and kept most steps";
  EXPECT_NE(kept.statistics.find("pair list built " + std::to_string(kept.list_builds) +
                                 " times in " + std::to_string(c.steps) + " steps"),
            std::string::npos)
      << kept.statistics;
}

class KeptPairList : public ::testing::TestWithParam<KeptListCase> {
 protected:
  void SetUp() override {
#ifndef TRIDEM_HAS_GMSH
    // The bonded specimen is a [[mesh]] region: a build without Gmsh refuses it (as the
    // bonded specimens' validation skips there).
    if (GetParam().scene == bonded) GTEST_SKIP() << "a build without Gmsh meshes no specimen";
#endif
  }
};

TEST_P(KeptPairList, SerialGivesTheBitsOfAListBuiltEveryStepInDouble) {
  expect_kept_list_is_exact<double>(GetParam(), Backend::Cpu);
}

TEST_P(KeptPairList, SerialGivesTheBitsOfAListBuiltEveryStepInFloat) {
  expect_kept_list_is_exact<float>(GetParam(), Backend::Cpu);
}

TEST_P(KeptPairList, OpenMpGivesTheBitsOfAListBuiltEveryStep) {
  expect_kept_list_is_exact<double>(GetParam(), Backend::OpenMP);
}

INSTANTIATE_TEST_SUITE_P(Scenes, KeptPairList, ::testing::ValuesIn(kCases),
                         [](const auto& scene) { return std::string(scene.param.name); });

// A restart in the middle of a kept list's life: the loaded state builds a new list, and the
// run goes on with the bits of one that never stopped.
TEST(KeptPairListRestart, ALoadedStateContinuesWithTheSameBits) {
  Scene s = test::jostling_pile(20, 12);
  const ParticleModel model = build_particle_model(s);
  const TimeStep ts = estimate_time_step(s, model);
  CpuSolver<double> straight(s, model, ts, SolverConfig{}, false);
  straight.advance(300);
  CpuSolver<double> first(s, model, ts, SolverConfig{}, false);
  first.advance(137);
  SolverState state;
  first.save_state(state);
  CpuSolver<double> second(s, model, ts, SolverConfig{}, false);
  second.load_state(state);
  second.advance(163);
  Snapshot a, b;
  straight.snapshot(a, true);
  second.snapshot(b, true);
  test::expect_identical(a, b);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
