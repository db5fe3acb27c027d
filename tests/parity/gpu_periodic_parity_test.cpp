// Periodic boundaries and Lees-Edwards shear on the CUDA backend (issue 15) against the
// serial reference: a pile periodic along x, a gas periodic in x and y, a sheared gas and
// the shear-flow example (bodies of triangles), with the grid and all-pairs, in double
// (support/gpu_compare.hpp's tolerances) and float (support/float_compare.hpp's, against
// the serial double run); a collision through the boundary equals the one away from it
// bit for bit on the GPU as on the CPU; backend = auto takes the GPU.
#include "support/backend_test.hpp"
#include "support/float_compare.hpp"
#include "support/gpu.hpp"
#include "support/gpu_compare.hpp"
#include "support/periodic_scenes.hpp"
#include "support/scene_builder.hpp"
#include "tridem/scene_io.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_agreement;

/// The case on the CPU and on the GPU with `method`, from the serial solver's state after
/// the warm-up, compared at every chunk in double (the parity tolerances), with the same
/// energy budget at the end (the boundaries' work included); contacts through the
/// boundaries must occur on the way, so that the scene tests what it is meant to.
void expect_periodic_agreement(const test::PeriodicParityCase& c, Method method) {
  const std::string what = c.name + ", " + std::string(method_name(method));
  const SolverState start = test::warmed_up_state(c, method);
  auto cpu = test::solver_from(c, Backend::Cpu, method, start);
  auto gpu = test::solver_from(c, Backend::Cuda, method, start);
  const std::size_t through =
      test::run_side_by_side(c, *cpu, *gpu, [&](const Snapshot& a, const Snapshot& b) {
        EXPECT_EQ(test::through_boundary(a), test::through_boundary(b)) << what;
        expect_agreement(a, b, (what + ", step " + std::to_string(a.step)).c_str());
      });
  EXPECT_GT(through, 0u) << what << ": the scene must touch through a boundary";
  const EnergyBudget ea = cpu->energy(), eb = gpu->energy();
  const double scale = 1e-9 * (std::abs(ea.wall_work) + ea.dissipated_damping +
                               ea.dissipated_friction + ea.elastic + 1e-12);
  std::printf("%s: wall work %.9g (cpu) %.9g (gpu) J/m\n", what.c_str(), ea.wall_work,
              eb.wall_work);
  EXPECT_NEAR(ea.wall_work, eb.wall_work, scale) << what;
  EXPECT_NEAR(ea.dissipated_damping, eb.dissipated_damping, scale) << what;
  EXPECT_NEAR(ea.dissipated_friction, eb.dissipated_friction, scale) << what;
  EXPECT_NEAR(ea.elastic, eb.elastic, scale) << what;
}

/// The parity cases of support/periodic_scenes.hpp: a pile periodic along x, a gas
/// periodic in x and y, two Lees-Edwards gases (the images above and below slide, the list
/// is rebuilt before they slide past its slack, the boundary's work is booked as on the
/// CPU) and the shear-flow example (bodies of triangles wrapping as a whole).
class GpuPeriodicParity : public ::testing::TestWithParam<Method> {
 protected:
  void SetUp() override { TRIDEM_SKIP_WITHOUT_GPU(); }
};

TEST_P(GpuPeriodicParity, DoubleAgreesWithSerial) {
  for (const test::PeriodicParityCase& c : test::periodic_parity_cases()) {
    if (GetParam() != Method::Grid && c.scene.triangles.size() > 200) continue;
    expect_periodic_agreement(c, GetParam());
  }
}

INSTANTIATE_TEST_SUITE_P(Gpu, GpuPeriodicParity,
                         ::testing::Values(Method::Grid, Method::AllPairs, Method::SingleDomain));

// The paper's single-domain kernel in a periodic cell: with the exact test it reproduces
// the CUDA grid bit for bit, as without a cell (GpuParity.SingleDomainExactReproducesCuda-
// GridBitForBit), pre-filter on or off.
TEST(GpuPeriodicSingleDomain, ExactReproducesTheCudaGridBitForBit) {
  TRIDEM_SKIP_WITHOUT_GPU();
  test::expect_periodic_single_domain_exact_is_the_grid(Backend::Cuda);
}

// Float pairs (the mixed mode) against the serial double run, with the float tolerances
// and their proof that gravity shows (support/periodic_scenes.hpp's periodic_float_scenes;
// periodic_test.cpp runs the CPU's float solver on them).
TEST(GpuPeriodicFloat, FloatStaysCloseToSerialDouble) {
  TRIDEM_SKIP_WITHOUT_GPU();
  for (const Scene& s : test::periodic_float_scenes()) {
    const std::int64_t steps = test::steps_for(s, test::kPeriodicFloatSeconds);
    const Snapshot tried = test::run_to(s, Backend::Cuda, steps, Precision::Float);
    EXPECT_GT(tried.contacts.size(), 0u) << "the float pairs must carry forces";
    test::expect_float_follows_double(s, steps, tried);
  }
}

// A collision exactly on the boundary is the collision away from it, bit for bit, on the
// GPU as on the CPU (periodic_test.cpp's PeriodicCollision): the same offsets, the same
// forces; and a contact keeps its friction history across its grains' wrap.
class GpuPeriodicCollision : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override { TRIDEM_SKIP_WITHOUT_GPU(); }
};

TEST_P(GpuPeriodicCollision, OnTheBoundaryEqualsAwayFromIt) {
  const int axis = GetParam();
  const Scene away = test::oblique_collision(axis, 3.25, 0);
  const Scene through = test::in_cell(away, axis, {0.5, -0.5});
  const int steps = test::steps_for(away, 0.0025);
  const test::Trajectory a = test::run_frames(away, Backend::Cuda, 40, steps);
  const test::Trajectory b = test::run_frames(through, Backend::Cuda, 40, steps);
  test::expect_same_collision(a, b, axis, {0.5, -0.5});
  std::size_t touching = 0;
  for (const Snapshot& s : b.frames) touching += test::through_boundary(s);
  EXPECT_GT(touching, 3u) << "the grains must touch through the boundary";
}

TEST_P(GpuPeriodicCollision, ContactKeepsItsFrictionHistoryAcrossAWrap) {
  const int axis = GetParam();
  const Scene away = test::oblique_collision(axis, 3.52, 4);
  const Scene through = test::in_cell(away, axis, {0, 0});
  const int steps = test::steps_for(away, 0.0025);
  test::expect_same_collision(test::run_frames(away, Backend::Cuda, 40, steps),
                              test::run_frames(through, Backend::Cuda, 40, steps), axis, {0, -1});
}

INSTANTIATE_TEST_SUITE_P(Gpu, GpuPeriodicCollision, ::testing::Values(0, 1));

// backend = auto runs periodic scenes on the GPU (it fell back to the CPU before), those
// whose cells are long enough for the GPU's list (PeriodicRefusal.CellTooShortForTheGpuList):
// the sheared gas of 5 pitches (4 are 0.4 m, under the 0.4005 m its grains and skin need).
TEST(GpuPeriodic, AutoBackendRunsPeriodicScenesOnTheGpu) {
  TRIDEM_SKIP_WITHOUT_GPU();
  for (Method m : {Method::Grid, Method::AllPairs}) {
    test::expect_auto_backend_takes_the_gpu(test::periodic_gas(4, 0.1),
                                            test::SolverChoice(Backend::Cuda, m));
    test::expect_auto_backend_takes_the_gpu(test::dense_sheared_gas(5),
                                            test::SolverChoice(Backend::Cuda, m));
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
