// generate_lattice: geometry, spacing, no overlap, counting, refusals.
#include "io/scene/generator_checks.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"
#include "triangle_overlap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

LatticeSpec lattice(Vec2d lo, Vec2d hi, double size, double gap) {
  LatticeSpec s;
  s.region_min = lo;
  s.region_max = hi;
  s.size = size;
  s.gap = gap;
  return s;
}

TEST(SceneLattice, EquilateralCounterClockwiseAndInsideRegion) {
  const LatticeSpec spec = lattice({-3, 2}, {7, 10}, 1.0, 0.1);
  const auto ts = generate_lattice(spec);
  ASSERT_EQ(ts.size(), count_lattice(spec));
  ASSERT_GT(ts.size(), 100u);
  for (const TriangleSpec& t : ts) {
    EXPECT_GT(test::twice_area(t.vertices), 0) << "clockwise";
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(norm(t.vertices[(i + 1) % 3] - t.vertices[i]), 1.0, 1e-12);
      EXPECT_GE(t.vertices[i].x, -3 - 1e-9);
      EXPECT_LE(t.vertices[i].x, 7 + 1e-9);
      EXPECT_GE(t.vertices[i].y, 2 - 1e-9);
      EXPECT_LE(t.vertices[i].y, 10 + 1e-9);
    }
  }
  // The first triangle is an up triangle with its left base corner on the region corner.
  EXPECT_DOUBLE_EQ(ts[0].vertices[0].x, -3);
  EXPECT_DOUBLE_EQ(ts[0].vertices[0].y, 2);
}

TEST(SceneLattice, NoOverlapAndNeighboursExactlyGapApart) {
  for (double gap : {0.05, 0.1, 0.5, 2.0}) {
    const auto ts = generate_lattice(lattice({0, 0}, {20, 20}, 1.0, gap));
    ASSERT_GE(ts.size(), 20u) << "gap " << gap;
    EXPECT_FALSE(test::find_overlap(ts, 1e-9)) << "gap " << gap;
    EXPECT_NEAR(test::min_separation(ts), gap * 1.0, 1e-9) << "gap " << gap;
  }
}

TEST(SceneLattice, ZeroGapTilesWithoutOverlap) {
  const auto ts = generate_lattice(lattice({0, 0}, {15, 13}, 1.0, 0.0));
  ASSERT_GT(ts.size(), 300u);
  EXPECT_FALSE(test::find_overlap(ts, 1e-9));
  EXPECT_NEAR(test::min_separation(ts), 0.0, 1e-9);
}

TEST(SceneLattice, RegionExactlyFiveEdgesWideHoldsNineInOneRow) {
  // Gap 0, width 5: slots at x = 0, 0.5, ..., 4 (9 of them), up and down alternating; one
  // row's height holds both the up and the down triangles.
  const auto ts = generate_lattice(lattice({0, 0}, {5, std::sqrt(3.0) / 2}, 1.0, 0.0));
  EXPECT_EQ(ts.size(), 9u);
}

TEST(SceneLattice, TopRowMayHoldOnlyUpTriangles) {
  // Down triangles stand gap·size/2 higher than the ups of their row.
  const double h = std::sqrt(3.0) / 2;
  const auto ts = generate_lattice(lattice({0, 0}, {3, h + 0.01}, 1.0, 0.1));
  ASSERT_FALSE(ts.empty());
  for (const auto& t : ts) EXPECT_DOUBLE_EQ(t.vertices[0].y, 0.0) << "only up triangles";
}

TEST(SceneLattice, CountMatchesGenerationOverManyShapes) {
  for (double w : {1.0, 1.3, 2.0, 4.7, 10.0})
    for (double h : {0.9, 1.7, 3.2, 8.0})
      for (double gap : {0.0, 0.1, 0.33}) {
        const LatticeSpec spec = lattice({0.5, -1}, {0.5 + w, -1 + h}, 0.8, gap);
        const std::size_t n = count_lattice(spec);
        if (n == 0) {
          EXPECT_THROW(generate_lattice(spec), SceneError);
        } else {
          const auto ts = generate_lattice(spec);
          EXPECT_EQ(ts.size(), n) << w << " x " << h << " gap " << gap;
          // Every slot made, none left at its default (zero) vertices.
          for (const TriangleSpec& t : ts)
            EXPECT_GT(test::twice_area(t.vertices), 0) << w << " x " << h << " gap " << gap;
        }
      }
}

// Past 65 536 triangles the rows are filled on the threads: the ids still go row by row
// from the bottom, left to right within a row, each slot once.
TEST(SceneLattice, ALargeLatticeIsMadeRowByRowLeftToRight) {
  const double gap = 0.1, a = 1 + gap * std::sqrt(3.0), row_pitch = 0.5 * std::sqrt(3.0) * a;
  const LatticeSpec spec = lattice({-5, 3}, {-5 + 400, 3 + 300}, 1.0, gap);
  const auto ts = generate_lattice(spec);
  ASSERT_EQ(ts.size(), count_lattice(spec));
  ASSERT_GT(ts.size(), 100000u);
  long long last_row = -1;
  double last_left = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const auto& v = ts[i].vertices;
    ASSERT_GT(test::twice_area(v), 0) << i;
    const double bottom = std::min({v[0].y, v[1].y, v[2].y});
    const double left = std::min({v[0].x, v[1].x, v[2].x});
    const auto row = static_cast<long long>(std::floor((bottom - 3) / row_pitch + 1e-9));
    ASSERT_TRUE(row > last_row || (row == last_row && left > last_left + 0.25 * a))
        << "triangle " << i << " (row " << row << ", left " << left << ") after row " << last_row
        << ", left " << last_left;
    last_row = row;
    last_left = left;
  }
}

TEST(SceneLattice, CopiesMaterialAndVelocity) {
  LatticeSpec spec = lattice({0, 0}, {3, 3}, 1, 0.1);
  spec.material = 2;
  spec.velocity = {0.5, -1};
  for (const auto& t : generate_lattice(spec)) {
    EXPECT_EQ(t.material, 2);
    EXPECT_EQ(t.velocity.x, 0.5);
    EXPECT_EQ(t.velocity.y, -1);
    EXPECT_EQ(t.motion, Motion::Free);
  }
}

TEST(SceneLattice, RefusesInvalidSpecs) {
  EXPECT_THROW(generate_lattice(lattice({0, 0}, {5, 5}, 0, 0.1)), SceneError);
  EXPECT_THROW(generate_lattice(lattice({0, 0}, {5, 5}, -1, 0.1)), SceneError);
  EXPECT_THROW(generate_lattice(lattice({0, 0}, {5, 5}, 1, -0.1)), SceneError);
  EXPECT_THROW(generate_lattice(lattice({5, 0}, {0, 5}, 1, 0.1)), SceneError);
  EXPECT_THROW(generate_lattice(lattice({0, 0}, {5, 0}, 1, 0.1)), SceneError);
  EXPECT_THROW(generate_lattice(lattice({0, 0}, {NAN, 5}, 1, 0.1)), SceneError);
  LatticeSpec bad_material = lattice({0, 0}, {5, 5}, 1, 0.1);
  bad_material.material = -1;
  EXPECT_THROW(generate_lattice(bad_material), SceneError);
}

TEST(SceneLattice, RefusesZeroAndTooManyTriangles) {
  try {
    generate_lattice(lattice({0, 0}, {0.5, 0.5}, 1, 0.1));
    ADD_FAILURE() << "expected SceneError";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("no whole triangle"), std::string::npos) << e.what();
  }
  // A units slip: millimetre grains in a kilometre box. Must be refused before allocating.
  const LatticeSpec huge = lattice({0, 0}, {1000, 1000}, 1e-3, 0.1);
  EXPECT_GT(count_lattice(huge), kMaxGeneratedTriangles);
  EXPECT_THROW(generate_lattice(huge), SceneError);
  // Astronomical counts saturate rather than overflow.
  EXPECT_GT(count_lattice(lattice({0, 0}, {1e200, 1e200}, 1e-200, 0)), kMaxGeneratedTriangles);
}

TEST(SceneLattice, MillionTrianglesInWellUnderASecond) {
  const LatticeSpec spec = lattice({0, 0}, {1100, 1000}, 1.0, 0.1);
  const auto start = std::chrono::steady_clock::now();
  const auto ts = generate_lattice(spec);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GT(ts.size(), 1'000'000u);
  RecordProperty("seconds", std::to_string(seconds));
  // Generous bound: catches accidental quadratic behaviour, not slow machines.
  EXPECT_LT(seconds, 5.0);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem

namespace tridem::scene_detail {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// tridem info on 1.1e8 generated triangles (a units slip) used 24 GB and was killed by the
// kernel with no message; the reader now refuses such a count before generating.
TEST(SceneMemory, CountThatCannotBeHeldIsRefusedNamingTheEstimate) {
  const std::size_t eight_gib = std::size_t{8} << 30;
  const std::string why = memory_shortfall(110'000'000, eight_gib);
  ASSERT_FALSE(why.empty());
  EXPECT_NE(why.find("110000000 triangles"), std::string::npos) << why;
  EXPECT_NE(why.find("8.0 GiB available"), std::string::npos) << why;
  EXPECT_TRUE(memory_shortfall(1'000'000, eight_gib).empty());
  // The estimate is at least what the triangles themselves take.
  EXPECT_GE(bytes_to_read(1000), 1000 * sizeof(TriangleSpec));
  EXPECT_GT(available_memory_bytes(), std::size_t{1} << 20);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::scene_detail
