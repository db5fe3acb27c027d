// The periodic broad phase's host/device rules (broadphase/periodic_grid.hpp) and the wrap
// with its work (physics/periodic_frame.hpp), which the CPU's CandidatePairs and the GPU's
// list builder and integrator share: tested here on the host.
#include "broadphase/grid_rules.hpp"
#include "broadphase/periodic_grid.hpp"
#include "physics/periodic_frame.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <set>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

physics::PeriodicFrame cell(bool px, bool py, double shear_rate = 0, double t = 0) {
  return physics::periodic_frame_at(px, -1.0, 2.0, py, 0.5, 1.5, shear_rate, t);
}

TEST(PeriodicGrid, CellsTileEachPeriodicDirection) {
  const PeriodicGrid g = fit_periodic_grid(cell(true, true), -5, -5, 5, 5, 0.3, 1e6);
  EXPECT_EQ(g.nx, 6);  // 2.0 / 0.3 = 6.67: 6 cells of 0.333
  EXPECT_EQ(g.ny, 5);  // 1.5 / 0.3 = 5
  EXPECT_DOUBLE_EQ(g.cell_x * static_cast<double>(g.nx), 2.0);
  EXPECT_DOUBLE_EQ(g.cell_y * static_cast<double>(g.ny), 1.5);
  EXPECT_GE(g.cell_x, 0.3);
  EXPECT_EQ(g.ox, -1.0);
  EXPECT_EQ(g.oy, 0.5);
}

TEST(PeriodicGrid, AnOpenDirectionIsGriddedAsTheCornersExtent) {
  const PeriodicGrid g = fit_periodic_grid(cell(true, false), -5, 0.2, 5, 1.1, 0.3, 1e6);
  const GridFit plain = fit_grid(10, 1.1 - 0.2, 0.3, 1e6);
  EXPECT_EQ(g.ny, plain.ny);
  EXPECT_EQ(g.cell_y, 0.3);
  EXPECT_EQ(g.oy, 0.2);
  // Past max_cells the cells grow, as fit_grid's do.
  const PeriodicGrid capped = fit_periodic_grid(cell(false, false), 0, 0, 10, 10, 0.1, 100);
  EXPECT_LE(capped.nx * capped.ny, 100);
  EXPECT_GT(capped.cell_x, 0.1);
}

TEST(PeriodicGrid, CornersAreBinnedModuloTheCell) {
  const PeriodicGrid g = fit_periodic_grid(cell(true, true), 0, 0, 0, 0, 0.5, 1e6);
  ASSERT_EQ(g.nx, 4);
  ASSERT_EQ(g.ny, 3);
  EXPECT_EQ(periodic_grid_cell(g, -0.9, 0.6), 0);
  // One period to the right and one above: the same cell.
  EXPECT_EQ(periodic_grid_cell(g, -0.9 + 2.0, 0.6 + 1.5), 0);
  // Just left of the cell: its last column.
  EXPECT_EQ(periodic_grid_cell(g, -1.01, 0.6), 3);
  // Just below the cell: its top row.
  EXPECT_EQ(periodic_grid_cell(g, -0.9, 0.49), 0 + 2 * 4);
}

TEST(PeriodicGrid, ALeesEdwardsCornerPastTheTopIsBinnedShiftedBack) {
  // Shift 0.6 at t = 1 (γ̇·Ly·t = 0.4 · 1.5 · 1).
  const physics::PeriodicFrame f = cell(true, true, 0.4, 1.0);
  ASSERT_DOUBLE_EQ(f.shift, 0.6);
  const PeriodicGrid g = fit_periodic_grid(f, 0, 0, 0, 0, 0.5, 1e6);
  // A corner one period above at x = 0.2 is the image at x = 0.2 − 0.6 of the cell.
  EXPECT_EQ(periodic_grid_cell(g, 0.2, 0.6 + 1.5), periodic_grid_cell(g, 0.2 - 0.6, 0.6));
  EXPECT_NE(periodic_grid_cell(g, 0.2, 0.6 + 1.5), periodic_grid_cell(g, 0.2, 0.6));
}

std::vector<std::int64_t> neighbours(const PeriodicGrid& g, double x, double y) {
  std::vector<std::int64_t> cells;
  for_each_periodic_neighbour_cell(g, x, y, periodic_grid_cell(g, x, y),
                                   [&](std::int64_t c) { cells.push_back(c); });
  return cells;
}

TEST(PeriodicGrid, TheScanReachesAcrossTheEdgesEachCellOnce) {
  const PeriodicGrid g = fit_periodic_grid(cell(true, true), 0, 0, 0, 0, 0.5, 1e6);  // 4 × 3
  const std::vector<std::int64_t> corner = neighbours(g, -0.99, 0.51);  // column 0, row 0
  const std::set<std::int64_t> distinct(corner.begin(), corner.end());
  EXPECT_EQ(corner.size(), 9u);
  EXPECT_EQ(distinct.size(), 9u);
  EXPECT_TRUE(distinct.count(3 + 2 * 4)) << "the opposite corner, across both edges";
  // An open y: the rows past the grid are not scanned.
  const PeriodicGrid open = fit_periodic_grid(cell(true, false), 0, 0.5, 0, 2.0, 0.5, 1e6);
  EXPECT_EQ(neighbours(open, -0.99, 0.51).size(), 6u);
  // A period of 2 cells is scanned whole, each cell once.
  const PeriodicGrid narrow = fit_periodic_grid(cell(true, true), 0, 0, 0, 0, 0.7, 1e6);
  ASSERT_EQ(narrow.ny, 2);
  const std::vector<std::int64_t> all = neighbours(narrow, 0.1, 1.0);
  EXPECT_EQ(all.size(), static_cast<std::size_t>(narrow.nx * narrow.ny));
  EXPECT_EQ(std::set<std::int64_t>(all.begin(), all.end()).size(), all.size());
}

TEST(PeriodicGrid, ALeesEdwardsRowIsScannedAboutTheShiftedCorner) {
  const physics::PeriodicFrame f = cell(true, true, 0.4, 1.0);        // shift 0.6
  const PeriodicGrid g = fit_periodic_grid(f, 0, 0, 0, 0, 0.5, 1e6);  // 4 × 3
  // A corner in the top row sees the bottom row's images shifted by +0.6: the columns about
  // x − 0.6 of the bottom row hold them.
  const double x = 0.3, y = 1.9;
  const std::vector<std::int64_t> cells = neighbours(g, x, y);
  const std::int64_t shifted = periodic_grid_cell(g, x - 0.6, 0.6);  // bottom row, shifted
  EXPECT_NE(std::find(cells.begin(), cells.end(), shifted), cells.end());
}

physics::Aabb<double> box(double lx, double ly, double hx, double hy) {
  return physics::box_of(lx, ly, hx, hy);
}

TEST(PeriodicBoxes, OverlapThroughTheNearestImage) {
  const physics::PeriodicFrame f = cell(true, true);
  // i near the right edge (x = 0.95), j near the left one (x = −0.95): 0.1 apart through x.
  const Vec2d ci{0.95, 1.0}, cj{-0.95, 1.0};
  EXPECT_TRUE(
      periodic_boxes_overlap(f, ci, cj, box(0.9, 0.95, 1.0, 1.05), box(-1.0, 0.95, -0.9, 1.05)));
  EXPECT_FALSE(
      periodic_boxes_overlap(f, ci, cj, box(0.9, 0.95, 0.94, 1.05), box(-0.95, 0.95, -0.9, 1.05)));
  // Without the cell the same boxes are far apart.
  EXPECT_FALSE(periodic_boxes_overlap(physics::PeriodicFrame{}, ci, cj, box(0.9, 0.95, 1.0, 1.05),
                                      box(-1.0, 0.95, -0.9, 1.05)));
}

TEST(PeriodicBoxes, TheShearedSlackWidensOnlyImagesAcrossTheShearedBoundary) {
  const physics::PeriodicFrame f = cell(true, true, 0.4, 1.0);  // shift 0.6
  // j one period above i: its image is moved by (−0.6, −1.5), to x in [0.15, 0.35], 0.05
  // short of i's box along x.
  const Vec2d ci{0.0, 0.6}, cj{0.9, 2.05};
  const auto bi = box(-0.1, 0.55, 0.1, 0.65), bj = box(0.75, 2.0, 0.95, 2.1);
  EXPECT_FALSE(periodic_boxes_overlap(f, ci, cj, bi, bj));
  EXPECT_TRUE(periodic_boxes_overlap(f, ci, cj, bi, bj, 0.1));
  // Through x only: the image is moved by −2 to x in [−1.1, −1.03], 0.05 short of i's box,
  // and the slack does not apply.
  const Vec2d ck{-0.95, 0.6}, cl{0.95, 0.6};
  const auto bk = box(-0.98, 0.55, -0.92, 0.65), bl = box(0.9, 0.55, 0.97, 0.65);
  EXPECT_FALSE(periodic_boxes_overlap(f, ck, cl, bk, bl));
  EXPECT_FALSE(periodic_boxes_overlap(f, ck, cl, bk, bl, 0.5));
  EXPECT_TRUE(periodic_boxes_overlap(f, ck, cl, box(-1.04, 0.55, -0.92, 0.65), bl));
}

TEST(PeriodicWrap, WrapWithWorkIsTheWrapAndItsEnergy) {
  const physics::PeriodicFrame f = cell(true, true, 0.4, 1.0);
  physics::Pose<double> p{{0.3, 2.1}, 0.2, {1.0, 2.0}, 3.0};
  physics::Pose<double> q = p;
  physics::wrap_into_cell(f, q);
  const double expected = physics::wrap_energy(p, q, 1.0 / 0.25, {0, -9.81});
  physics::Pose<double> r = p;
  EXPECT_EQ(physics::wrap_with_work(f, r, 0.25, {0, -9.81}), expected);
  EXPECT_EQ(r.c.x, q.c.x);
  EXPECT_EQ(r.c.y, q.c.y);
  EXPECT_EQ(r.v.x, q.v.x);
  EXPECT_NEAR(r.c.y, 2.1 - 1.5, 1e-15);
  EXPECT_NEAR(r.v.x, 1.0 - 0.4 * 1.5, 1e-15);
  EXPECT_GT(std::abs(expected), 0);
  physics::Pose<double> inside{{0.3, 1.0}, 0, {1, 0}, 0};
  EXPECT_EQ(physics::wrap_with_work(f, inside, 0.25, {0, -9.81}), 0.0);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
