// Cohesive bonds on the CUDA solver against the serial reference (issue 14), every method,
// double and float: a bonded disc loaded by a fast platen, whose bonds are damaged and
// broken within the run (support/bonded_disc.hpp). The comparison, its tolerances and why
// (pointwise within a rounding twin's envelope; in float, pointwise over the first
// kFloatPointwiseSteps, then by the fracture's statistics) are support/bond_compare.hpp's;
// validation/unstable_parity_test.cpp proves on the CPU that it fails for a wrong bond
// and passes for a run of other rounding. The measured differences are printed.
#include "support/backend_test.hpp"
#include "support/bond_compare.hpp"
#include "support/bonded_disc.hpp"
#include "tridem/error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

void expect_bonds_agree(const test::SolverChoice& choice, const Scene& scene, std::int64_t steps,
                        std::int64_t every) {
  auto gpu = test::solver_for(scene, choice);
  ASSERT_NE(gpu->description().find(backend_name(Backend::Cuda)), std::string::npos);
  test::expect_bonds_agree(scene, test::SolverChoice(Backend::Cpu, choice.method, choice.precision),
                           *gpu, steps, every);
}

using GpuBondParity = test::BackendTest;

TEST_P(GpuBondParity, LoadedDiscAgreesWithSerial) {
  Scene s;
  try {
    s = test::loaded_bonded_disc();
  } catch (const SceneError& e) {
    GTEST_SKIP() << e.what();  // a build without Gmsh
  }
  if (GetParam().method == Method::Decomposition)
    s = test::with_decomposition(s, DecompositionLayout::Grid, 200);
  expect_bonds_agree(GetParam(), s, test::kLoadedDiscSteps, 100);
}

// backend = auto takes the GPU for a bonded scene (it fell back to the CPU before).
TEST_P(GpuBondParity, AutoBackendRunsBondsOnTheGpu) {
  Scene s;
  try {
    s = test::loaded_bonded_disc();
  } catch (const SceneError& e) {
    GTEST_SKIP() << e.what();
  }
  test::expect_auto_backend_takes_the_gpu(s, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Gpu, GpuBondParity, TRIDEM_SOLVER_CHOICES(::tridem::Backend::Cuda));

// All-pairs: the grid path's kernels with another list.
TEST(GpuBondParityAllPairs, LoadedDiscAgreesWithSerial) {
  TRIDEM_SKIP_WITHOUT_GPU();
  Scene s;
  try {
    s = test::loaded_bonded_disc();
  } catch (const SceneError& e) {
    GTEST_SKIP() << e.what();
  }
  expect_bonds_agree(test::SolverChoice(Backend::Cuda, Method::AllPairs), s, test::kLoadedDiscSteps,
                     100);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
