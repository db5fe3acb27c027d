// How scattered in memory the neighbours of consecutive particles are
// (core/neighbour_blocks): low for points numbered by rows, along a curve, or along a curve
// and then sheared (their neighbours stay in a few runs of indices); high at random.
#include "core/neighbour_blocks.hpp"
#include "core/space_filling_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

constexpr int kSide = 300;  ///< points of the lattice a side, one grain size apart

/// A kSide x kSide lattice of points one apart, row by row.
std::vector<Vec2d> lattice() {
  std::vector<Vec2d> p;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) p.push_back({static_cast<double>(x), static_cast<double>(y)});
  return p;
}

/// `points` put in the order of `key(point)` along the Hilbert curve.
template <class Key>
std::vector<Vec2d> along_curve(const std::vector<Vec2d>& points, Key key) {
  std::vector<Vec2d> keys(points.size());
  std::transform(points.begin(), points.end(), keys.begin(), key);
  std::vector<Vec2d> out;
  for (const std::size_t i : space_filling_order(keys)) out.push_back(points[i]);
  return out;
}

double spread(const std::vector<Vec2d>& points) {
  return neighbour_block_spread(points, std::vector<std::uint8_t>(points.size(), 1), 1.0);
}

TEST(NeighbourBlocks, OrderedPointsHaveTheirNeighboursInFewBlocksAndRandomOnesInMany) {
  const std::vector<Vec2d> rows = lattice();
  const double by_rows = spread(rows);
  const double by_curve = spread(along_curve(rows, [](Vec2d p) { return p; }));
  // Numbered along the curve, then sheared by 30 (the order's curve ran through x - 30 y).
  const double sheared = spread(along_curve(rows, [](Vec2d p) {
    return Vec2d{p.x - 30 * p.y, p.y};
  }));
  std::vector<Vec2d> shuffled = rows;
  std::mt19937_64 random(3);
  std::shuffle(shuffled.begin(), shuffled.end(), random);
  const double at_random = spread(shuffled);
  EXPECT_GE(by_rows, 1.0);
  EXPECT_LT(by_rows, 4.0);
  EXPECT_LT(by_curve, 4.0);
  EXPECT_LT(sheared, 4.0);
  EXPECT_GT(at_random, 3 * kScatteredNeighbours);
}

TEST(NeighbourBlocks, OnlyFreeParticlesCountAndTooFewGiveZero) {
  std::vector<Vec2d> shuffled = lattice();
  std::mt19937_64 random(3);
  std::shuffle(shuffled.begin(), shuffled.end(), random);
  // Every other particle a wall: the free ones are as scattered.
  std::vector<std::uint8_t> free(shuffled.size(), 0);
  for (std::size_t i = 0; i < free.size(); i += 2) free[i] = 1;
  EXPECT_GT(neighbour_block_spread(shuffled, free, 1.0), kScatteredNeighbours);
  // Walls only, or no size: nothing to tell.
  EXPECT_EQ(neighbour_block_spread(shuffled, std::vector<std::uint8_t>(free.size(), 0), 1.0), 0);
  EXPECT_EQ(neighbour_block_spread(shuffled, free, 0.0), 0);
  const std::vector<Vec2d> few(shuffled.begin(), shuffled.begin() + 20);
  EXPECT_EQ(spread(few), 0);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
