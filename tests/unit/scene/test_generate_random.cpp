// generate_random: no overlap, region, count, shapes, determinism, refusals.
#include "io/scene/triangle_shape.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"
#include "triangle_overlap.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

RandomPackingSpec packing(Vec2d lo, Vec2d hi, double size, double gap, double irregularity = 0,
                          std::uint64_t seed = 1, std::size_t count = 0) {
  RandomPackingSpec s;
  s.region_min = lo;
  s.region_max = hi;
  s.size = size;
  s.gap = gap;
  s.irregularity = irregularity;
  s.seed = seed;
  s.count = count;
  return s;
}

void expect_inside(const std::vector<TriangleSpec>& ts, Vec2d lo, Vec2d hi) {
  for (const auto& t : ts)
    for (const Vec2d& v : t.vertices) {
      ASSERT_GE(v.x, lo.x);
      ASSERT_LE(v.x, hi.x);
      ASSERT_GE(v.y, lo.y);
      ASSERT_LE(v.y, hi.y);
    }
}

TEST(SceneRandom, FillsGridWithoutOverlapInsideRegion) {
  for (double gap : {0.0, 0.1, 0.5})
    for (double irregularity : {0.0, 0.5, 0.95}) {
      const RandomPackingSpec spec = packing({-2, 1}, {28, 26}, 1.0, gap, irregularity, 7);
      const auto ts = generate_random(spec);
      ASSERT_EQ(ts.size(), count_random_cells(spec));
      ASSERT_GE(ts.size(), 200u);
      expect_inside(ts, spec.region_min, spec.region_max);
      EXPECT_FALSE(test::find_overlap(ts, 0.0)) << "gap " << gap << " irr " << irregularity;
    }
}

TEST(SceneRandom, GapKeepsCircumdisksApart) {
  // Jitter is at most R·gap/2 per axis, so circumdisks of neighbouring cells keep at least
  // R·gap apart along each axis, and so do the triangles inside them.
  const double R = 1 / std::sqrt(3.0);
  const auto ts = generate_random(packing({0, 0}, {15, 15}, 1.0, 0.2, 0.3, 3));
  EXPECT_GE(test::min_separation(ts), R * 0.2 - 1e-12);
}

TEST(SceneRandom, ShapesAreCounterClockwiseAndFarFromDegenerate) {
  const double R = 1 / std::sqrt(3.0);
  for (double irregularity : {0.0, 0.5, 0.999}) {
    for (const auto& t : generate_random(packing({0, 0}, {30, 30}, 1.0, 0.1, irregularity, 11))) {
      EXPECT_FALSE(scene_detail::shape_problem(t.vertices));
      // The documented lower bound on area (radii >= R/2, angular gaps in (π/3, π)).
      EXPECT_GT(0.5 * test::twice_area(t.vertices), 0.2 * R * R);
      // Never larger than the circumscribed disk allows.
      for (int i = 0; i < 3; ++i)
        EXPECT_LE(norm(t.vertices[(i + 1) % 3] - t.vertices[i]), 2 * R + 1e-12);
    }
  }
}

TEST(SceneRandom, IrregularityZeroGivesEquilateralOfEdgeSize) {
  for (const auto& t : generate_random(packing({0, 0}, {10, 10}, 0.7, 0.1)))
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(norm(t.vertices[(i + 1) % 3] - t.vertices[i]), 0.7, 1e-12);
}

TEST(SceneRandom, SameSeedSameTrianglesOtherSeedOthers) {
  const auto a = generate_random(packing({0, 0}, {10, 10}, 1, 0.2, 0.4, 42));
  const auto b = generate_random(packing({0, 0}, {10, 10}, 1, 0.2, 0.4, 42));
  const auto c = generate_random(packing({0, 0}, {10, 10}, 1, 0.2, 0.4, 43));
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), c.size());
  bool differs = false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(a[i].vertices[k].x, b[i].vertices[k].x);
      EXPECT_EQ(a[i].vertices[k].y, b[i].vertices[k].y);
      differs = differs || a[i].vertices[k].x != c[i].vertices[k].x;
    }
  EXPECT_TRUE(differs);
}

TEST(SceneRandom, FollowsTheDocumentedDrawOrder) {
  // Pins the recipe (raw mt19937_64 → top 53 bits; draws jx, jy, θ0, then per vertex turn
  // and radius) so that packings stay reproducible; recomputed here without the generator.
  const double R = 1 / std::sqrt(3.0);
  const double pitch = 2 * R * 1.1;
  const auto ts = generate_random(packing({0, 0}, {10, 10}, 1, 0.1, 0, 5));
  std::mt19937_64 rng(5);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const std::size_t nx = static_cast<std::size_t>(10 / pitch);
  for (std::size_t i = 0; i < 3 * nx; ++i) {
    const double jx = 0.05 * R * (2 * u() - 1), jy = 0.05 * R * (2 * u() - 1);
    const double theta0 = 2 * std::numbers::pi * u();
    for (int k = 0; k < 6; ++k) u();  // turns and radii: no effect at irregularity 0
    const Vec2d centre{(static_cast<double>(i % nx) + 0.5) * pitch + jx,
                       (static_cast<double>(i / nx) + 0.5) * pitch + jy};
    EXPECT_NEAR(ts[i].vertices[0].x, centre.x + R * std::cos(theta0), 1e-12) << i;
    EXPECT_NEAR(ts[i].vertices[0].y, centre.y + R * std::sin(theta0), 1e-12) << i;
  }
}

TEST(SceneRandom, IrregularityChangesShapesNotPlacement) {
  // Every triangle takes the same nine draws whatever the irregularity, so its centre and
  // its orientation θ0 do not depend on it. At irregularity 0 the triangle is equilateral
  // about its centre, which is then its centroid; at irregularity ι, vertex k is at a
  // radius in [R(1 − ι/2), R] from that same centre and turned by at most ι·π/6 from
  // vertex k of the regular triangle. A centre or θ0 that moved with ι (even by a fraction
  // of the jitter, here up to R/4 per axis) puts vertices outside these bounds.
  const double R = 1 / std::sqrt(3.0), irregularity = 0.6, eps = 1e-12;
  const auto regular = generate_random(packing({0, 0}, {20, 20}, 1, 0.5, 0.0, 9));
  const auto irregular = generate_random(packing({0, 0}, {20, 20}, 1, 0.5, irregularity, 9));
  ASSERT_EQ(regular.size(), irregular.size());
  ASSERT_GE(regular.size(), 100u);
  const double max_turn = irregularity * std::numbers::pi / 6;
  for (std::size_t i = 0; i < regular.size(); ++i) {
    const auto& a = regular[i].vertices;
    const Vec2d centre = (a[0] + a[1] + a[2]) / 3.0;
    for (int k = 0; k < 3; ++k) {
      const Vec2d ra = a[k] - centre, rb = irregular[i].vertices[k] - centre;
      ASSERT_NEAR(norm(ra), R, eps) << "triangle " << i;
      EXPECT_LE(norm(rb), R + eps) << "triangle " << i << ", vertex " << k;
      EXPECT_GE(norm(rb), R * (1 - irregularity / 2) - eps) << "triangle " << i << ", vertex " << k;
      EXPECT_LE(std::abs(std::atan2(cross(ra, rb), dot(ra, rb))), max_turn + eps)
          << "triangle " << i << ", vertex " << k;
    }
  }
}

TEST(SceneRandom, StopsAtCountFillingBottomRowFirst) {
  const RandomPackingSpec spec = packing({0, 0}, {10, 10}, 1, 0.1, 0.2, 1, 13);
  const auto ts = generate_random(spec);
  ASSERT_EQ(ts.size(), 13u);
  // The full packing with the same seed starts with the same triangles.
  const auto full = generate_random(packing({0, 0}, {10, 10}, 1, 0.1, 0.2, 1, 0));
  for (std::size_t i = 0; i < ts.size(); ++i)
    EXPECT_EQ(ts[i].vertices[2].y, full[i].vertices[2].y);
}

TEST(SceneRandom, RefusesInvalidSpecs) {
  EXPECT_THROW(generate_random(packing({0, 0}, {5, 5}, 0, 0.1)), SceneError);
  EXPECT_THROW(generate_random(packing({0, 0}, {5, 5}, 1, -0.1)), SceneError);
  EXPECT_THROW(generate_random(packing({0, 0}, {5, 5}, 1, 0.1, 1.0)), SceneError);
  EXPECT_THROW(generate_random(packing({0, 0}, {5, 5}, 1, 0.1, -0.1)), SceneError);
  EXPECT_THROW(generate_random(packing({0, 5}, {5, 0}, 1, 0.1)), SceneError);
  EXPECT_THROW(generate_random(packing({0, 0}, {0.5, 0.5}, 1, 0.1)), SceneError);
  EXPECT_THROW(generate_random(packing({0, 0}, {1000, 1000}, 1e-3, 0.1)), SceneError);
  const RandomPackingSpec small = packing({0, 0}, {5, 5}, 1, 0.1);
  EXPECT_THROW(generate_random(packing({0, 0}, {5, 5}, 1, 0.1, 0, 1,
                                       count_random_cells(small) + 1)),
               SceneError);
}

TEST(SceneRandom, MillionTrianglesInWellUnderASecond) {
  const auto start = std::chrono::steady_clock::now();
  const auto ts = generate_random(packing({0, 0}, {1300, 1300}, 1, 0.1, 0.3, 1, 1'000'000));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(ts.size(), 1'000'000u);
  RecordProperty("seconds", std::to_string(seconds));
  EXPECT_LT(seconds, 5.0);  // generous: catches accidental quadratic behaviour only
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
