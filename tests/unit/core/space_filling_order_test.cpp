// The Hilbert curve that numbers generated grains by where they lie (numbering = "space"):
// it visits every cell of a square once, each step to a side neighbour, and the order it
// gives points keeps neighbours near each other.
#include "core/space_filling_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(SpaceFillingOrder, TheCurveVisitsEachCellOfACornerSquareOnceBySideSteps) {
  // The curve's first 4^k cells are the corner square of side 2^k (its first quadrant is
  // the lower left one at every level).
  constexpr std::uint32_t side = 256;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cell_at(side * side, {side, side});
  for (std::uint32_t x = 0; x < side; ++x)
    for (std::uint32_t y = 0; y < side; ++y) {
      const std::uint64_t d = hilbert_index(x, y);
      ASSERT_LT(d, cell_at.size()) << x << ", " << y;
      ASSERT_EQ(cell_at[d].first, side) << "cell " << d << " visited twice";
      cell_at[d] = {x, y};
    }
  for (std::size_t d = 1; d < cell_at.size(); ++d) {
    const auto [x0, y0] = cell_at[d - 1];
    const auto [x1, y1] = cell_at[d];
    const long step = std::labs(static_cast<long>(x1) - static_cast<long>(x0)) +
                      std::labs(static_cast<long>(y1) - static_cast<long>(y0));
    ASSERT_EQ(step, 1) << "from cell " << d - 1 << " to " << d;
  }
  EXPECT_EQ(hilbert_index(0, 0), 0u);
  EXPECT_EQ(hilbert_index(65535, 0), (std::uint64_t{1} << 32) - 1);  // where it ends
}

TEST(SpaceFillingOrder, OrdersScatteredPointsSoThatNeighboursFollowEachOther) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> at(-2.0, 5.0);
  std::vector<Vec2d> points(20000);
  for (Vec2d& p : points) p = {at(random), at(random)};
  const std::vector<std::size_t> order = space_filling_order(points);
  ASSERT_EQ(order.size(), points.size());
  std::vector<std::size_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);  // a permutation
  auto mean_step = [&](auto index) {
    double sum = 0;
    for (std::size_t i = 1; i < points.size(); ++i)
      sum += norm(points[index(i)] - points[index(i - 1)]);
    return sum / static_cast<double>(points.size() - 1);
  };
  const double given = mean_step([](std::size_t i) { return i; });
  const double curved = mean_step([&](std::size_t i) { return order[i]; });
  // Random points lie ~3.7 apart in this 7 x 7 square; along the curve, about the spacing
  // of 20 000 points in it (0.05).
  EXPECT_GT(given, 3.0);
  EXPECT_LT(curved, 0.1);
}

TEST(SpaceFillingOrder, NumbersTheFirstTrianglesByPlaceAndLeavesTheRest) {
  std::mt19937_64 random(9);
  std::uniform_real_distribution<double> at(0.0, 10.0);
  std::vector<TriangleSpec> triangles(5000);
  for (TriangleSpec& t : triangles) {
    const Vec2d c{at(random), at(random)};
    t.vertices = {c, c + Vec2d{0.01, 0}, c + Vec2d{0, 0.01}};
  }
  std::vector<TriangleSpec> numbered = triangles;
  number_by_place(numbered, 4990);
  auto x_of = [](const std::vector<TriangleSpec>& ts) {
    std::vector<double> x;
    for (const TriangleSpec& t : ts) x.push_back(t.vertices[0].x);
    return x;
  };
  const std::vector<double> before = x_of(triangles), after = x_of(numbered);
  for (std::size_t i = 4990; i < 5000; ++i) EXPECT_EQ(after[i], before[i]);  // left in place
  std::vector<double> a(before.begin(), before.begin() + 4990),
      b(after.begin(), after.begin() + 4990);
  EXPECT_NE(a, b);
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);  // the same triangles
  double step = 0;
  for (std::size_t i = 1; i < 4990; ++i)
    step += norm(numbered[i].vertices[0] - numbered[i - 1].vertices[0]);
  EXPECT_LT(step / 4989, 0.5);  // ~0.14 along the curve, ~5 in the given order
}

TEST(SpaceFillingOrder, KeepsTheOrderOfPointsInOneCellAndOfNone) {
  EXPECT_TRUE(space_filling_order({}).empty());
  const std::vector<Vec2d> same(5, Vec2d{1, 2});
  const std::vector<std::size_t> order = space_filling_order(same);
  for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], i);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
