// The decomposition method on the GPU (one block per sub-domain, the bookkeeping on the
// host) against the serial reference: the cell grid, which the CPU decomposition
// reproduces bit for bit. Small capacities force many sub-domains, migrations and border
// moves; the agreement is the CUDA backend's usual one (support/gpu_compare.hpp).
#include "support/gpu.hpp"
#include "support/gpu_compare.hpp"
#include "support/periodic_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/error.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <string>
#include <utility>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

void expect_agrees_with_serial(const Scene& s, std::int64_t steps, const char* what) {
  const Snapshot cpu = test::run_to(s, Backend::Cpu, steps);
  const auto gpu = test::advanced_solver(s, Backend::Cuda, steps, Precision::Double,
                                         Method::Decomposition);
  Snapshot snap;
  gpu->snapshot(snap, true);
  EXPECT_GT(cpu.contacts.size(), 20u) << what << ": the pile must be in contact";
  test::expect_agreement(cpu, snap, what);
  const std::string stats = gpu->statistics();
  std::printf("%s: %s\n", what, stats.c_str());
  EXPECT_NE(stats.find("sub-domains"), std::string::npos) << stats;
}

TEST(GpuDecomposition, StripsAgreeWithSerial) {
  TRIDEM_SKIP_WITHOUT_GPU();
  expect_agrees_with_serial(
      test::with_decomposition(test::jostling_pile(40, 4), DecompositionLayout::Strips, 24), 200,
      "1d, capacity 24");
}

TEST(GpuDecomposition, RowsAndColumnsAgreeWithSerial) {
  TRIDEM_SKIP_WITHOUT_GPU();
  expect_agrees_with_serial(
      test::with_decomposition(test::jostling_pile(20, 12), DecompositionLayout::Grid, 24), 200,
      "2d automatic, capacity 24");
  expect_agrees_with_serial(
      test::with_decomposition(test::jostling_pile(20, 12, 6), DecompositionLayout::Grid, 32, 3, 4),
      200, "2d 3 x 4, capacity 32");
}

TEST(GpuDecomposition, PaperCapacityAgreesWithSerial) {
  TRIDEM_SKIP_WITHOUT_GPU();
  expect_agrees_with_serial(
      test::with_decomposition(test::jostling_pile(60, 20, 7), DecompositionLayout::Grid, 256),
      200, "2d automatic, capacity 256");
}

TEST(GpuDecomposition, TwoRunsAreBitIdentical) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s =
      test::with_decomposition(test::jostling_pile(20, 12), DecompositionLayout::Grid, 24);
  for (Precision p : {Precision::Double, Precision::Float})
    test::expect_identical(test::run_to(s, Backend::Cuda, 200, p, Method::Decomposition),
                           test::run_to(s, Backend::Cuda, 200, p, Method::Decomposition));
}

TEST(GpuDecomposition, DirectAreaTestMissesTheEdgeCrossingPair) {
  TRIDEM_SKIP_WITHOUT_GPU();
  Scene s = test::empty_scene();
  s.triangles.push_back(test::triangle({0, 1}, {-0.866, -0.5}, {0.866, -0.5}));
  s.triangles.push_back(test::triangle({0, -1}, {0.866, 0.5}, {-0.866, 0.5}));
  s.simulation.decomposition.capacity = 2;
  EXPECT_EQ(test::run_to(s, Backend::Cuda, 1, Precision::Double, Method::Decomposition)
                .contacts.size(),
            1u);
  s.simulation.contact_test = ContactTest::DirectArea;
  EXPECT_EQ(test::run_to(s, Backend::Cuda, 1, Precision::Double, Method::Decomposition)
                .contacts.size(),
            0u);
}

// In periodic cells (along x; both ways; both ways with Lees-Edwards shear) the GPU's
// sub-domains by a boundary stage the images of the particles across it
// (assignment_kernels.cuh's visit_bands: the host's rule, from the particle's side, each
// particle once): the CUDA grid's state bit for bit, in strips and in rows and columns, in
// double and float, with contacts through the boundaries and particles migrating between
// sub-domains (decomposition_parity_test.cpp's PeriodicCellsReproduceGridBitForBit on the
// CPU). Without the images the pairs through the boundaries are missed.
TEST(GpuDecomposition, PeriodicCellsReproduceTheCudaGridBitForBit) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const std::pair<const char*, Scene> cases[] = {
      {"periodic pile", test::periodic_pile(12, 6)},
      {"periodic gas", test::periodic_gas(10, 0.1, 0.49)},
      {"dense sheared gas", test::dense_sheared_gas(10)}};
  for (const auto& [name, scene] : cases)
    for (const auto layout : {DecompositionLayout::Strips, DecompositionLayout::Grid})
      for (const Precision precision : {Precision::Double, Precision::Float}) {
        const Scene s = test::with_decomposition(scene, layout, 40);
        SCOPED_TRACE(fmt::format("{}, {}, {}", name,
                                 layout == DecompositionLayout::Grid ? "2d" : "1d",
                                 precision == Precision::Float ? "float" : "double"));
        const Snapshot grid = test::run_to(s, Backend::Cuda, 600, precision, Method::Grid);
        const auto dd =
            test::advanced_solver(s, Backend::Cuda, 600, precision, Method::Decomposition);
        Snapshot snap;
        dd->snapshot(snap, true);
        test::expect_identical(grid, snap);
        EXPECT_GT(test::through_boundary(grid), 0u) << "contacts through the boundaries";
        const std::string stats = dd->statistics();
        EXPECT_EQ(stats.find("decomposition: 1 sub-domains"), std::string::npos) << stats;
        EXPECT_EQ(stats.find(" 0 migrations"), std::string::npos) << stats;
      }
}

TEST(GpuDecomposition, CapacityBeyondSharedMemoryIsRefused) {
  TRIDEM_SKIP_WITHOUT_GPU();
  Scene s = test::with_decomposition(test::jostling_pile(4, 2), DecompositionLayout::Strips,
                                     100000);
  try {
    test::run_to(s, Backend::Cuda, 1, Precision::Double, Method::Decomposition);
    FAIL() << "expected a RunError";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("shared memory"), std::string::npos) << e.what();
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
