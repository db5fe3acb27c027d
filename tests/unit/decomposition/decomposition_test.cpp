// The decomposition's bookkeeping on its own: ownership is unique, each sub-domain stays
// within its capacity, every pair the cell grid finds is a candidate of exactly one
// sub-domain, borders move when a sub-domain overflows, particles migrate as they move,
// and a column that cannot fit is refused with a message that says what to change; the
// GPU's rule for the bands (decomposition/band_visit.hpp) finds the host's lists, in
// periodic cells too.
#include "unit/decomposition/triangle_cloud.hpp"

#include "broadphase/candidate_pairs.hpp"
#include "decomposition/band_visit.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::PairSet;
using test::TriangleCloud;

Decomposition<double> make(const TriangleCloud& c, DecompositionLayout layout, int capacity,
                           int rows = 0, int columns = 0) {
  const GridClasses classes = classify_for_grid(c.longest_edge, c.motion);
  DecompositionSettings s;
  s.layout = layout;
  s.capacity = capacity;
  s.rows = rows;
  s.columns = columns;
  return Decomposition<double>(s, classes.cell, classes.small);
}

bool boxes_overlap(const TriangleCloud& c, std::int32_t i, std::int32_t j) {
  return c.lo_x[i] <= c.hi_x[j] && c.lo_x[j] <= c.hi_x[i] && c.lo_y[i] <= c.hi_y[j] &&
         c.lo_y[j] <= c.hi_y[i];
}

/// The candidates each sub-domain finds among what it stages: its owned emitters against
/// higher-index staged particles, and against every large one; the grid's rules for the
/// rest (boxes overlap, at least one free). Sorted; a pair found twice stays twice.
PairSet decomposition_pairs(const Decomposition<double>& d, const TriangleCloud& c) {
  PairSet out;
  auto free = [&c](std::int32_t p) { return c.motion[p] == Motion::Free; };
  for (int k = 0; k < d.count(); ++k) {
    const auto staged = d.members(k);
    for (const std::int32_t i : staged) {
      if (d.owner(i) != k) continue;
      for (const std::int32_t j : staged)
        if (j > i && (free(i) || free(j)) && boxes_overlap(c, i, j)) out.emplace_back(i, j);
      for (const std::int32_t j : d.large())
        if ((free(i) || free(j)) && boxes_overlap(c, i, j)) out.emplace_back(i, j);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The hull of each sub-domain's owned boxes (empty: lo above hi).
std::vector<Hull<double>> hulls_of(const Decomposition<double>& d, const TriangleCloud& c) {
  std::vector<Hull<double>> hull(static_cast<std::size_t>(d.count()));
  for (int k = 0; k < d.count(); ++k) {
    hull[k] = {1e300, 1e300, -1e300, -1e300};
    for (const std::int32_t p : d.owned(k))
      hull[k] = {std::min(hull[k].lo_x, c.lo_x[p]), std::min(hull[k].lo_y, c.lo_y[p]),
                 std::max(hull[k].hi_x, c.hi_x[p]), std::max(hull[k].hi_y, c.hi_y[p])};
  }
  return hull;
}

/// The bands the GPU finds from the particles' side (visit_bands over the hulls of the
/// owned boxes, through the images in a periodic cell), in the order of its lists: each
/// sub-domain's particles ascending.
std::vector<std::vector<std::int32_t>> particle_side_bands(const Decomposition<double>& d,
                                                           const TriangleCloud& c,
                                                           const physics::PeriodicFrame* periodic) {
  const GridClasses classes = classify_for_grid(c.longest_edge, c.motion);
  const std::vector<Hull<double>> hull = hulls_of(d, c);
  Hull<double> extent{1e300, 1e300, -1e300, -1e300};
  for (int k = 0; k < d.count(); ++k)
    if (d.owned(k).size() > 0)
      extent = {std::min(extent.lo_x, hull[k].lo_x), std::min(extent.lo_y, hull[k].lo_y),
                std::max(extent.hi_x, hull[k].hi_x), std::max(extent.hi_y, hull[k].hi_y)};
  const AssignmentView<double> view{static_cast<int>(c.size()),
                                    d.count(),
                                    d.map(),
                                    classes.small.data(),
                                    c.x.data(),
                                    c.y.data(),
                                    c.lo_x.data(),
                                    c.lo_y.data(),
                                    c.hi_x.data(),
                                    c.hi_y.data(),
                                    periodic ? *periodic : physics::PeriodicFrame{},
                                    periodic ? &extent : nullptr};
  std::vector<std::vector<std::int32_t>> bands(static_cast<std::size_t>(d.count()));
  for (std::size_t p = 0; p < c.size(); ++p)
    if (classes.small[p])
      visit_bands(view, hull.data(), static_cast<int>(p),
                  [&](int k) { bands[k].push_back(static_cast<std::int32_t>(p)); });
  return bands;
}

/// The ownership checks of one step, and the particles' side's bands against the lists.
void expect_owned_and_staged(const Decomposition<double>& d, const TriangleCloud& c,
                             const physics::PeriodicFrame* periodic = nullptr) {
  const GridClasses classes = classify_for_grid(c.longest_edge, c.motion);
  std::vector<int> times_owned(c.size(), 0);
  for (int k = 0; k < d.count(); ++k) {
    const auto owned = d.owned(k);
    const auto staged = d.members(k);
    EXPECT_LE(static_cast<int>(staged.size()), d.capacity()) << "sub-domain " << k;
    EXPECT_TRUE(std::is_sorted(staged.begin(), staged.end())) << "sub-domain " << k;
    for (const std::int32_t p : owned) {
      ++times_owned[p];
      EXPECT_EQ(d.owner(p), k);
      EXPECT_TRUE(std::binary_search(staged.begin(), staged.end(), p))
          << "particle " << p << " owned but not staged by " << k;
    }
  }
  for (std::size_t p = 0; p < c.size(); ++p)
    EXPECT_EQ(times_owned[p], classes.small[p] ? 1 : 0) << "particle " << p;
  // Ownership by centroid: the owner is the sub-domain of the centroid's cell.
  const DomainMap m = d.map();
  for (std::size_t p = 0; p < c.size(); ++p) {
    if (!classes.small[p]) continue;
    EXPECT_EQ(d.owner(p), m.owner(decomposition_cell(c.y[p], m.origin_y, m.cell),
                                  decomposition_cell(c.x[p], m.origin_x, m.cell)));
  }
  const auto bands = particle_side_bands(d, c, periodic);
  for (int k = 0; k < d.count(); ++k)
    EXPECT_EQ(bands[k], std::vector<std::int32_t>(d.members(k).begin(), d.members(k).end()))
        << "sub-domain " << k;
}

/// Every check of the bookkeeping at one step.
void expect_consistent(const Decomposition<double>& d, const TriangleCloud& c) {
  expect_owned_and_staged(d, c);
  const PairSet grid = test::grid_pairs(c);
  PairSet sorted_grid = grid;
  std::sort(sorted_grid.begin(), sorted_grid.end());
  EXPECT_EQ(decomposition_pairs(d, c), sorted_grid);
}

struct LayoutCase {
  DecompositionLayout layout;
  int capacity, rows, columns;
};

class DecompositionBookkeeping : public ::testing::TestWithParam<LayoutCase> {};

TEST_P(DecompositionBookkeeping, OwnershipUniqueAndEveryGridPairFoundOnce) {
  const LayoutCase lc = GetParam();
  for (unsigned seed : {1u, 2u, 3u}) {
    const TriangleCloud c = test::random_cloud(600, 3.0, 1.0, 0.05, seed);
    Decomposition<double> d = make(c, lc.layout, lc.capacity, lc.rows, lc.columns);
    d.update(c.input());
    EXPECT_GT(d.count(), 4) << "the capacity must force many sub-domains";
    expect_consistent(d, c);
    EXPECT_GT(test::grid_pairs(c).size(), 300u);
  }
}

TEST_P(DecompositionBookkeeping, MigrationKeepsEveryPairAndMovesBorders) {
  const LayoutCase lc = GetParam();
  TriangleCloud c = test::random_cloud(500, 3.0, 1.0, 0.05, 7);
  Decomposition<double> d = make(c, lc.layout, lc.capacity, lc.rows, lc.columns);
  // The same with OpenMP: every list and count must be the serial one.
  Decomposition<double> threaded = make(c, lc.layout, lc.capacity, lc.rows, lc.columns);
  d.update(c.input());
  threaded.update(c.input(), true);
  const GridClasses classes = classify_for_grid(c.longest_edge, c.motion);
  // Particles drift and gather towards x = 1.5: sub-domains there fill up.
  for (int step = 0; step < 40; ++step) {
    for (std::size_t p = 0; p < c.size(); ++p)
      if (classes.small[p] && c.motion[p] == Motion::Free)
        c.shift(p, {0.005 * (1.5 - c.x[p]), 0.003 * std::sin(3.0 * c.x[p] + step)});
    d.update(c.input());
    threaded.update(c.input(), true);
    expect_consistent(d, c);
    EXPECT_EQ(d.member_offset(), threaded.member_offset());
    EXPECT_EQ(d.member_list(), threaded.member_list());
    EXPECT_EQ(d.summary(), threaded.summary());
    if (testing::Test::HasFailure()) return;
  }
  const DecompositionStats& s = d.stats();
  EXPECT_EQ(s.updates, 41);
  EXPECT_GT(s.migrations, 100);
  EXPECT_GT(s.overflows, 0);
  EXPECT_GT(s.border_moves + s.repartitions, 0);
  EXPECT_LE(s.max_members, lc.capacity);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, DecompositionBookkeeping,
    ::testing::Values(LayoutCase{DecompositionLayout::Strips, 96, 0, 0},
                      LayoutCase{DecompositionLayout::Strips, 128, 0, 6},
                      LayoutCase{DecompositionLayout::Grid, 40, 0, 0},
                      LayoutCase{DecompositionLayout::Grid, 48, 3, 4}));

// In a periodic cell the sub-domains by a boundary stage the particles whose images reach
// them (Decomposition::stage_images, from the sub-domains' side); the GPU finds the same
// lists from the particles' side (visit_bands), each particle once, however many images
// reach a sub-domain: along x, both ways, and both ways with a Lees-Edwards shift, while
// the particles drift and borders move.
TEST_P(DecompositionBookkeeping, PeriodicBandsFromEitherSideAreTheSame) {
  const LayoutCase lc = GetParam();
  struct Cell {
    bool py;
    double shift;
  };
  for (const Cell cell : {Cell{false, 0}, Cell{true, 0}, Cell{true, 0.7}}) {
    TriangleCloud c = test::random_cloud(500, 3.0, 1.0, 0.05, 3);
    Decomposition<double> d = make(c, lc.layout, lc.capacity, lc.rows, lc.columns);
    physics::PeriodicFrame f;
    f.px = true;
    f.x0 = 0;
    f.lx = 3.0;
    f.py = cell.py;
    f.y0 = 0;
    f.ly = 1.0;
    f.shift = cell.shift;
    const GridClasses classes = classify_for_grid(c.longest_edge, c.motion);
    std::size_t through = 0;
    for (int step = 0; step < 12; ++step) {
      d.update(c.input(), false, &f);
      SCOPED_TRACE(::testing::Message()
                   << "periodic y " << cell.py << ", shift " << cell.shift << ", step " << step);
      expect_owned_and_staged(d, c, &f);
      if (testing::Test::HasFailure()) return;
      // Staged though its box does not reach the hull: an image of it does.
      const std::vector<Hull<double>> hull = hulls_of(d, c);
      for (int k = 0; k < d.count(); ++k)
        for (const std::int32_t p : d.members(k))
          through += !box_reaches(c.lo_x[p], c.lo_y[p], c.hi_x[p], c.hi_y[p], hull[k]);
      // Drift along x through the boundary (wrapped back into the cell).
      for (std::size_t p = 0; p < c.size(); ++p)
        if (classes.small[p] && c.motion[p] == Motion::Free) {
          const double dx = c.x[p] + 0.09 >= 3.0 ? 0.09 - 3.0 : 0.09;
          c.shift(p, {dx, 0});
        }
    }
    EXPECT_GT(through, 0u) << "sub-domains by the boundaries must stage images";
    EXPECT_GT(d.stats().migrations, 0);
  }
}

TEST(Decomposition, OverflowMovesBorderToNeighbour) {
  // Three strips of equal counts; then particles of the right one move into the middle.
  TriangleCloud c = test::random_cloud(200, 4.0, 0.3, 0.05, 11);
  Decomposition<double> d = make(c, DecompositionLayout::Strips, 90, 0, 3);
  d.update(c.input());
  ASSERT_EQ(d.count(), 3);
  for (std::size_t p = 0; p < c.size(); ++p)
    if (c.x[p] > 2.7 && c.x[p] < 3.3 && c.longest_edge[p] < 0.2) c.shift(p, {-0.4, 0});
  d.update(c.input());
  expect_consistent(d, c);
  EXPECT_GT(d.stats().overflows, 0);
  EXPECT_GT(d.stats().border_moves + d.stats().repartitions, 0);
}

TEST(Decomposition, ColumnThatCannotFitIsRefusedWithAdvice) {
  // A tall stack: one cell column holds far more than the capacity.
  TriangleCloud c;
  for (int i = 0; i < 60; ++i) {
    const double y = 0.06 * i;
    const Vec2d v[3] = {{0, y}, {0.05, y}, {0.02, y + 0.05}};
    c.add(v, Motion::Free);
  }
  Decomposition<double> d = make(c, DecompositionLayout::Strips, 32);
  try {
    d.update(c.input());
    FAIL() << "expected a RunError";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cell column 0"), std::string::npos) << what;
    EXPECT_NE(what.find("stage 60 particles"), std::string::npos) << what;
    EXPECT_NE(what.find("capacity 32"), std::string::npos) << what;
    EXPECT_NE(what.find("layout = \"2d\""), std::string::npos) << what;
  }
  // In 2D with enough rows the same stack fits.
  Decomposition<double> rows = make(c, DecompositionLayout::Grid, 32, 6);
  rows.update(c.input());
  expect_consistent(rows, c);
}

TEST(Decomposition, CapacityBelowTwoIsRefused) {
  const TriangleCloud c = test::random_cloud(10, 1, 1, 0.05, 1);
  EXPECT_THROW(make(c, DecompositionLayout::Strips, 1), SceneError);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
