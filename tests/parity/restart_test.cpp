// Restart bit-identity: a run stopped at step N/2, saved through a checkpoint file's bytes
// and loaded into a fresh solver ends at step N exactly where an uninterrupted run does,
// on each backend and precision. The pile has friction, so the contact history must
// survive the round trip: RestartWithoutHistoryDiverges shows that it matters here.
#include "support/backend_test.hpp"
#include "support/body_scenes.hpp"
#include "support/bonded_disc.hpp"
#include "support/gpu.hpp"
#include "support/periodic_scenes.hpp"
#include "support/program_scenes.hpp"
#include "support/scene_builder.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"
#include "tridem/solver.hpp"

#include <gtest/gtest.h>
#include <omp.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

constexpr std::int64_t kSteps = 400;

std::unique_ptr<Solver> solver_for(const Scene& s, Backend backend, Precision precision,
                                   Method method = Method::Grid) {
  return test::solver_for(s, test::SolverChoice(backend, method, precision));
}

/// The state after steps/2, through the checkpoint encoding and back.
SolverState halfway_state(const Scene& s, Backend backend, Precision precision,
                          Method method = Method::Grid, std::int64_t steps = kSteps) {
  auto first = solver_for(s, backend, precision, method);
  first->advance(steps / 2);
  Checkpoint c;
  first->save_state(c.state);
  c.meta = {precision, scene_fingerprint(s), {}};
  return decode_checkpoint(encode_checkpoint(c), "test").state;
}

SolverState final_state(Solver& solver, std::int64_t steps = kSteps) {
  solver.advance(steps - solver.step());
  SolverState out;
  solver.save_state(out);
  return out;
}

void expect_bit_identical(const SolverState& a, const SolverState& b) {
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.time, b.time);
  for (auto member : {&SolverState::x, &SolverState::y, &SolverState::theta, &SolverState::vx,
                      &SolverState::vy, &SolverState::omega}) {
    const auto& va = a.*member;
    const auto& vb = b.*member;
    ASSERT_EQ(va.size(), vb.size());
    for (std::size_t i = 0; i < va.size(); ++i) ASSERT_EQ(va[i], vb[i]) << "particle " << i;
  }
  EXPECT_EQ(a.pair_emitter, b.pair_emitter);
  EXPECT_EQ(a.pair_partner, b.pair_partner);
  EXPECT_EQ(a.pair_slip, b.pair_slip);
  // The energy budget's cumulative sums, per particle, so that energy.csv continues exactly.
  for (int k = 0; k < kEnergyAccumulators; ++k) {
    ASSERT_EQ(a.energy[k].size(), a.x.size()) << "energy sums " << k;
    EXPECT_EQ(a.energy[k], b.energy[k]) << "energy sums " << k;
  }
  // Bodies of several triangles: their own pose and velocities.
  SolverState::for_each_body_column([&](auto field) {
    EXPECT_EQ(a.column(field), b.column(field)) << "body " << decltype(field)::name;
  });
}

void expect_restart_exact(Backend backend, Precision precision, Method method = Method::Grid,
                          const Scene& s = test::jostling_pile(12, 8), std::int64_t steps = kSteps,
                          std::size_t min_pairs = 10) {
  auto straight = solver_for(s, backend, precision, method);
  const SolverState expected = final_state(*straight, steps);

  const SolverState half = halfway_state(s, backend, precision, method, steps);
  ASSERT_GT(half.pairs(), min_pairs) << "the scene must carry contact history at the restart";
  double damping = 0;
  for (double e : half.energy[kDissipatedDamping]) damping += e;
  ASSERT_GT(damping, 0) << "the pile must carry dissipated energy at the restart";
  auto restarted = solver_for(s, backend, precision, method);
  restarted->load_state(half);
  expect_bit_identical(final_state(*restarted, steps), expected);
}

/// expect_restart_exact for scenes of bodies of several triangles, over `steps` steps:
/// the halfway state must hold bodies in contact with history.
void expect_body_restart_exact(const test::SolverChoice& c, const Scene& s, std::int64_t steps) {
  auto straight = solver_for(s, c.backend, c.precision, c.method);
  const SolverState expected = final_state(*straight, steps);
  ASSERT_GT(expected.bodies(), 1u);
  const SolverState half = halfway_state(s, c.backend, c.precision, c.method, steps);
  ASSERT_EQ(half.bodies(), expected.bodies());
  ASSERT_GT(half.pairs(), 0u) << "the bodies must carry contact history at the restart";
  auto restarted = solver_for(s, c.backend, c.precision, c.method);
  restarted->load_state(half);
  expect_bit_identical(final_state(*restarted, steps), expected);
}

// Bodies: colliding polygons on a fixed body, and a pile of bodies settling on a floor,
// every method, double and float; serial, OpenMP and CUDA (instances Cpu/, OpenMP/, Gpu/).
using BodyRestart = test::BackendTest;

TEST_P(BodyRestart, CollidingBodiesAreBitIdentical) {
  expect_body_restart_exact(GetParam(), test::colliding_bodies(), 3000);
}

TEST_P(BodyRestart, SettlingPileOfBodiesIsBitIdentical) {
  Scene s = test::settling_body_pile();
  if (GetParam().method == Method::Decomposition)
    s = test::with_decomposition(s, DecompositionLayout::Grid, 200);
  expect_body_restart_exact(GetParam(), s, 400);
}

TRIDEM_INSTANTIATE_SOLVERS(BodyRestart);
// OpenMP: the grid in double and the decomposition in float (every method would add minutes
// on a loaded machine: the OpenMP runs of these small scenes are bound by thread start-up).
INSTANTIATE_TEST_SUITE_P(OpenMP, BodyRestart,
                         ::testing::Values(test::SolverChoice(Backend::OpenMP),
                                           test::SolverChoice(Backend::OpenMP,
                                                              Method::Decomposition,
                                                              Precision::Float)));

// Cohesive bonds: a loaded disc whose bonds are damaged at the checkpoint and break after
// it (support/bonded_disc.hpp); the checkpoint carries each point's damage and released
// energy (the broken flags follow from them), so the restarted run breaks the same bonds at
// the same steps and ends bit for bit where the straight one does, every backend.
using BondRestart = test::BackendTest;

TEST_P(BondRestart, LoadedDiscIsBitIdentical) {
  const test::SolverChoice& c = GetParam();
  Scene s;
  try {
    s = test::loaded_bonded_disc();
  } catch (const SceneError& e) {
    GTEST_SKIP() << e.what();  // a build without Gmsh
  }
  if (c.method == Method::Decomposition)
    s = test::with_decomposition(s, DecompositionLayout::Grid, 200);
  const std::int64_t steps = 2 * test::kLoadedDiscDamagedBy;
  auto straight = solver_for(s, c.backend, c.precision, c.method);
  const SolverState expected = final_state(*straight, steps);
  const SolverState half = halfway_state(s, c.backend, c.precision, c.method, steps);
  ASSERT_GT(test::count_bonds(half).damaged, 0u) << "bonds must be damaged at the restart";
  ASSERT_GT(test::count_bonds(expected).broken, test::count_bonds(half).broken)
      << "bonds must break after the restart";
  auto restarted = solver_for(s, c.backend, c.precision, c.method);
  restarted->load_state(half);
  const SolverState got = final_state(*restarted, steps);
  expect_bit_identical(got, expected);
  EXPECT_EQ(got.bond_damage, expected.bond_damage);
  EXPECT_EQ(got.bond_dissipated, expected.bond_dissipated);
  EXPECT_EQ(restarted->energy().dissipated_fracture, straight->energy().dissipated_fracture);
  EXPECT_EQ(restarted->energy().elastic, straight->energy().elastic);
}

TRIDEM_INSTANTIATE_SOLVERS(BondRestart);
INSTANTIATE_TEST_SUITE_P(OpenMP, BondRestart,
                         ::testing::Values(test::SolverChoice(Backend::OpenMP)));

// Motion programs and a servo: nothing but the walls' poses and velocities carries them
// (the time is the step's), so a restart continues them bit for bit.
using ProgramRestart = test::BackendTest;
TEST_P(ProgramRestart, ServoAndOscillatingWallsAreBitIdentical) {
  const test::SolverChoice& c = GetParam();
  expect_restart_exact(c.backend, c.precision, c.method, test::programmed_pile(12, 8));
}
// A servo whose length follows a lid (length_between): its target is a function of the
// walls' poses, which the checkpoint holds.
TEST_P(ProgramRestart, ServoFollowingALengthIsBitIdentical) {
  const test::SolverChoice& c = GetParam();
  for (const Scene& s : {test::servo_box(true), test::servo_box_of_bodies(true)}) {
    const std::int64_t steps = 3000;  // the grains have landed and the servo touches them
    auto straight = solver_for(s, c.backend, c.precision, c.method);
    const SolverState expected = final_state(*straight, steps);
    const SolverState half = halfway_state(s, c.backend, c.precision, c.method, steps);
    ASSERT_GT(half.pairs(), 0u) << "the grains must carry contact history at the restart";
    auto restarted = solver_for(s, c.backend, c.precision, c.method);
    restarted->load_state(half);
    expect_bit_identical(final_state(*restarted, steps), expected);
  }
}
INSTANTIATE_TEST_SUITE_P(Cpu, ProgramRestart, ::testing::Values(test::SolverChoice(Backend::Cpu)));
INSTANTIATE_TEST_SUITE_P(Gpu, ProgramRestart, ::testing::Values(test::SolverChoice(Backend::Cuda)));

// Periodic cells: the wraps, the images and the Lees-Edwards frame are functions of the
// state and of the step's time, which the checkpoint holds, so a restart continues them
// bit for bit (and the boundary's work in the wall-work sums).
using PeriodicRestart = test::BackendTest;
TEST_P(PeriodicRestart, PileAlongXIsBitIdentical) {
  const test::SolverChoice& c = GetParam();
  expect_restart_exact(c.backend, c.precision, c.method, test::periodic_pile(12, 8));
}
TEST_P(PeriodicRestart, ShearedGasIsBitIdentical) {
  const test::SolverChoice& c = GetParam();
  // 1200 steps: by the restart the gas has met itself, through the boundaries too.
  expect_restart_exact(c.backend, c.precision, c.method, test::dense_sheared_gas(10), 1200, 2);
}
INSTANTIATE_TEST_SUITE_P(Cpu, PeriodicRestart,
                         ::testing::Values(test::SolverChoice(Backend::Cpu),
                                           test::SolverChoice(Backend::Cpu, Method::AllPairs),
                                           test::SolverChoice(Backend::Cpu, Method::Grid,
                                                              Precision::Float)));
INSTANTIATE_TEST_SUITE_P(Gpu, PeriodicRestart,
                         ::testing::Values(test::SolverChoice(Backend::Cuda),
                                           test::SolverChoice(Backend::Cuda, Method::AllPairs),
                                           test::SolverChoice(Backend::Cuda, Method::Grid,
                                                              Precision::Float)));

TEST(Restart, SerialDoubleIsBitIdentical) { expect_restart_exact(Backend::Cpu, Precision::Double); }
TEST(Restart, SerialFloatIsBitIdentical) { expect_restart_exact(Backend::Cpu, Precision::Float); }

TEST(Restart, SingleDomainIsBitIdentical) {
  expect_restart_exact(Backend::Cpu, Precision::Double, Method::SingleDomain);
}

// A restarted decomposition groups the particles afresh: other borders, the same pairs.
TEST(Restart, DecompositionIsBitIdentical) {
  expect_restart_exact(Backend::Cpu, Precision::Double, Method::Decomposition,
                       test::with_decomposition(test::jostling_pile(12, 8),
                                                DecompositionLayout::Grid, 24));
}

TEST(Restart, OpenMPIsBitIdentical) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(3);
  expect_restart_exact(Backend::OpenMP, Precision::Double);
  omp_set_num_threads(saved);
}

TEST(Restart, RestartWithoutHistoryDiverges) {
  const Scene s = test::jostling_pile(12, 8);
  auto straight = solver_for(s, Backend::Cpu, Precision::Double);
  const SolverState expected = final_state(*straight);
  SolverState half = halfway_state(s, Backend::Cpu, Precision::Double);
  half.pair_emitter.clear();
  half.pair_partner.clear();
  half.pair_slip.clear();
  auto restarted = solver_for(s, Backend::Cpu, Precision::Double);
  restarted->load_state(half);
  const SolverState got = final_state(*restarted);
  EXPECT_NE(got.x, expected.x) << "dropping the friction history must change the run, or the "
                                  "restart tests do not test it";
}

TEST(GpuRestart, DoubleIsBitIdentical) {
  TRIDEM_SKIP_WITHOUT_GPU();
  expect_restart_exact(Backend::Cuda, Precision::Double);
}

TEST(GpuRestart, FloatIsBitIdentical) {
  TRIDEM_SKIP_WITHOUT_GPU();
  expect_restart_exact(Backend::Cuda, Precision::Float);
}

TEST(GpuRestart, SingleDomainIsBitIdentical) {
  TRIDEM_SKIP_WITHOUT_GPU();
  expect_restart_exact(Backend::Cuda, Precision::Double, Method::SingleDomain);
}

TEST(GpuRestart, DecompositionIsBitIdentical) {
  TRIDEM_SKIP_WITHOUT_GPU();
  expect_restart_exact(Backend::Cuda, Precision::Double, Method::Decomposition,
                       test::with_decomposition(test::jostling_pile(12, 8),
                                                DecompositionLayout::Grid, 24));
}

// The GPU's list also holds pairs within its skin that do not touch; its saved history
// must still be the CPU's: the same pairs, and slips that agree to rounding.
TEST(GpuRestart, SavesTheSameHistoryAsTheCpu) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s = test::jostling_pile(12, 8);
  const SolverState cpu = halfway_state(s, Backend::Cpu, Precision::Double);
  const SolverState gpu = halfway_state(s, Backend::Cuda, Precision::Double);
  ASSERT_GT(cpu.pairs(), 10u);
  EXPECT_EQ(gpu.pair_emitter, cpu.pair_emitter);
  ASSERT_EQ(gpu.pair_partner, cpu.pair_partner);
  for (std::size_t k = 0; k < cpu.pairs(); ++k)
    for (int e = 0; e < kSlipsPerPair; ++e)
      EXPECT_NEAR(gpu.pair_slip[k][e], cpu.pair_slip[k][e], 1e-12) << "pair " << k;
}

// A checkpoint does not name its backend: a CPU state continued on the GPU stays with the
// CPU run to rounding.
TEST(GpuRestart, ContinuesACpuCheckpoint) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s = test::jostling_pile(12, 8);
  auto straight = solver_for(s, Backend::Cpu, Precision::Double);
  const SolverState expected = final_state(*straight);
  auto gpu = solver_for(s, Backend::Cuda, Precision::Double);
  gpu->load_state(halfway_state(s, Backend::Cpu, Precision::Double));
  const SolverState got = final_state(*gpu);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(got.x[i], expected.x[i], 1e-9) << "particle " << i;
    EXPECT_NEAR(got.y[i], expected.y[i], 1e-9) << "particle " << i;
  }
}

TEST(Restart, StateAtStepZeroHasNoHistory) {
  auto solver = solver_for(test::jostling_pile(4, 3), Backend::Cpu, Precision::Double);
  SolverState s;
  solver->save_state(s);
  EXPECT_EQ(s.step, 0);
  EXPECT_EQ(s.pairs(), 0u);
  EXPECT_EQ(s.size(), solver->size());
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
