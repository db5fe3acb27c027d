// The decomposition method on the CPU against the serial cell grid. With the exact contact
// test it lists the grid's pairs less those that are certainly apart (zero force, and
// their history would be reset anyway), in the same rows, so the runs agree bit for bit;
// small capacities force many sub-domains, migrations and border moves on the way. OpenMP
// over sub-domains reproduces the serial run exactly.
#include "support/periodic_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/scene_io.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>
#include <string>
#include <utility>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

struct RunResult {
  Snapshot snap;
  std::string statistics;
};

RunResult run(const Scene& s, Backend backend, Method method, std::int64_t steps,
        Precision precision = Precision::Double) {
  const auto solver = test::advanced_solver(s, backend, steps, precision, method);
  RunResult r;
  solver->snapshot(r.snap, true);
  r.statistics = solver->statistics();
  return r;
}

/// Runs the scene with the grid and with the decomposition, serially, and expects the same
/// state bit for bit and sub-domains that did move.
void expect_same_as_grid(const Scene& s, std::int64_t steps, const char* what) {
  const RunResult grid = run(s, Backend::Cpu, Method::Grid, steps);
  const RunResult dd = run(s, Backend::Cpu, Method::Decomposition, steps);
  SCOPED_TRACE(what);
  test::expect_identical(grid.snap, dd.snap);
  EXPECT_EQ(grid.snap.contacts.size(), dd.snap.contacts.size());
  EXPECT_GT(grid.snap.contacts.size(), 30u) << "the scene must be in contact";
  std::printf("%s: %s\n", what, dd.statistics.c_str());
  EXPECT_NE(dd.statistics.find("sub-domains"), std::string::npos) << dd.statistics;
  EXPECT_EQ(dd.statistics.find(" 0 migrations"), std::string::npos) << dd.statistics;
}

TEST(DecompositionParity, StripsReproduceGridBitForBit) {
  // 500 steps: with the contact model of issue 10 the grains of these thin piles meet a
  // little later (29 and 27 contacts at 300 steps).
  expect_same_as_grid(test::with_decomposition(test::jostling_pile(40, 4), DecompositionLayout::Strips, 24),
                      500, "1d, capacity 24");
  expect_same_as_grid(test::with_decomposition(test::jostling_pile(30, 5, 9), DecompositionLayout::Strips, 32),
                      500, "1d, capacity 32");
}

TEST(DecompositionParity, RowsAndColumnsReproduceGridBitForBit) {
  expect_same_as_grid(test::with_decomposition(test::jostling_pile(20, 12), DecompositionLayout::Grid, 24),
                      300, "2d automatic, capacity 24");
  expect_same_as_grid(
      test::with_decomposition(test::jostling_pile(20, 12, 6), DecompositionLayout::Grid, 32, 3, 4),
      300, "2d 3 x 4, capacity 32");
}

TEST(DecompositionParity, ExampleScenesReproduceGridBitForBit) {
  // Grains thrown down at 3 m/s, so that the piles form within a short run.
  for (const char* name : {"settling_pile", "hopper"}) {
    Scene s = read_scene(std::string(TRIDEM_SOURCE_DIR) + "/examples/" + name + ".toml");
    for (TriangleSpec& t : s.triangles)
      if (t.motion == Motion::Free) t.velocity.y -= 3;
    expect_same_as_grid(test::with_decomposition(s, DecompositionLayout::Grid, 48), 4000, name);
  }
}

// In periodic cells (along x; both ways; both ways with Lees-Edwards shear) sub-domains by
// the boundaries stage the images of the particles across them: the grid's pairs, bit for
// bit, with contacts through the boundaries, in strips and in rows and columns.
TEST(DecompositionParity, PeriodicCellsReproduceGridBitForBit) {
  const std::pair<const char*, Scene> cases[] = {
      {"periodic pile", test::periodic_pile(12, 6)},
      {"periodic gas", test::periodic_gas(10, 0.1, 0.49)},
      {"dense sheared gas", test::dense_sheared_gas(10)}};
  for (const auto& [name, scene] : cases)
    for (const auto layout : {DecompositionLayout::Strips, DecompositionLayout::Grid}) {
      const Scene s = test::with_decomposition(scene, layout, 40);
      const RunResult grid = run(s, Backend::Cpu, Method::Grid, 600);
      const RunResult dd = run(s, Backend::Cpu, Method::Decomposition, 600);
      SCOPED_TRACE(fmt::format("{}, {}", name, layout == DecompositionLayout::Grid ? "2d" : "1d"));
      test::expect_identical(grid.snap, dd.snap);
      EXPECT_GT(test::through_boundary(grid.snap), 0u) << "contacts through the boundaries";
      EXPECT_EQ(dd.statistics.find("decomposition: 1 sub-domains"), std::string::npos)
          << dd.statistics;
      EXPECT_EQ(dd.statistics.find(" 0 migrations"), std::string::npos) << dd.statistics;
    }
}

TEST(DecompositionParity, PeriodicFloatAndOpenMPReproduceTheirGrids) {
  const Scene s =
      test::with_decomposition(test::dense_sheared_gas(10), DecompositionLayout::Grid, 40);
  test::expect_identical(run(s, Backend::Cpu, Method::Grid, 300, Precision::Float).snap,
                         run(s, Backend::Cpu, Method::Decomposition, 300, Precision::Float).snap);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(3);
  test::expect_identical(run(s, Backend::Cpu, Method::Decomposition, 300).snap,
                         run(s, Backend::OpenMP, Method::Decomposition, 300).snap);
  omp_set_num_threads(saved);
}

TEST(DecompositionParity, FloatReproducesFloatGridBitForBit) {
  const Scene s = test::with_decomposition(test::jostling_pile(20, 6), DecompositionLayout::Grid, 24);
  test::expect_identical(run(s, Backend::Cpu, Method::Grid, 200, Precision::Float).snap,
                         run(s, Backend::Cpu, Method::Decomposition, 200, Precision::Float).snap);
}

TEST(DecompositionParity, OpenMPReproducesSerialBitForBit) {
  const int saved = omp_get_max_threads();
  for (const auto layout : {DecompositionLayout::Strips, DecompositionLayout::Grid}) {
    const Scene s = test::with_decomposition(test::jostling_pile(40, 5), layout, 32);
    const RunResult serial = run(s, Backend::Cpu, Method::Decomposition, 300);
    for (int threads : {2, 3, 4}) {
      omp_set_num_threads(threads);
      const RunResult parallel = run(s, Backend::OpenMP, Method::Decomposition, 300);
      test::expect_identical(serial.snap, parallel.snap);
      EXPECT_EQ(serial.statistics, parallel.statistics);
    }
    omp_set_num_threads(saved);
  }
}

TEST(DecompositionParity, WithoutPrefilterTheSamePairsAreFound) {
  Scene s = test::with_decomposition(test::jostling_pile(20, 6), DecompositionLayout::Strips, 48);
  const RunResult with = run(s, Backend::Cpu, Method::Decomposition, 200);
  s.simulation.bbox_prefilter = false;
  test::expect_identical(with.snap, run(s, Backend::Cpu, Method::Decomposition, 200).snap);
}

TEST(DecompositionParity, DirectAreaTestMissesTheEdgeCrossingPair) {
  // Two triangles forming a hexagram overlap with no vertex inside the other: the exact test
  // gives them a force, the paper's direct area test none.
  Scene s = test::empty_scene();
  s.triangles.push_back(test::triangle({0, 1}, {-0.866, -0.5}, {0.866, -0.5}));
  s.triangles.push_back(test::triangle({0, -1}, {0.866, 0.5}, {-0.866, 0.5}));
  s.simulation.decomposition.capacity = 2;
  const RunResult exact = run(s, Backend::Cpu, Method::Decomposition, 1);
  EXPECT_EQ(exact.snap.contacts.size(), 1u);
  s.simulation.contact_test = ContactTest::DirectArea;
  const RunResult direct = run(s, Backend::Cpu, Method::Decomposition, 1);
  EXPECT_EQ(direct.snap.contacts.size(), 0u);
  EXPECT_EQ(direct.snap.fx[0], 0.0);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
