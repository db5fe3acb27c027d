#pragma once
// The broad phase's rules in a periodic cell (physics/periodic_frame.hpp), on the host and
// the device alike: the CPU's CandidatePairs and the GPU's list builder bin, scan and test
// boxes by these functions, so that both see across the boundaries the same way.
//
// Along a periodic direction the grid's cells tile the period exactly (n cells of
// period/n, no smaller than the grid's cell) and a corner's cell is taken modulo n; across
// a Lees-Edwards y boundary a corner past the cell is binned as the image that brings it
// back, shifted along x with it. A direction that is not periodic is binned as the plain
// grid bins it (clamped to its cells).
#include "physics/geometry.hpp"
#include "physics/periodic_frame.hpp"
#include "tridem/hd.hpp"

#include <cfloat>
#include <cstdint>
#include <math.h>

namespace tridem {

/// The periodic grid of one build: n cells of cell_x × cell_y from (ox, oy), and the
/// Lees-Edwards shift of the frame it was built in.
struct PeriodicGrid {
  bool px = false, py = false;
  std::int64_t nx = 1, ny = 1;
  double cell_x = 0, cell_y = 0, ox = 0, oy = 0, shift = 0;
};

/// The grid for small particles' corners in [min, max] with cells no smaller than `cell`;
/// past `max_cells` the cells grow (more candidates, the same pairs), as fit_grid's do.
TRIDEM_HD inline PeriodicGrid fit_periodic_grid(const physics::PeriodicFrame& f, double min_x,
                                                double min_y, double max_x, double max_y,
                                                double cell, double max_cells) {
  PeriodicGrid g;
  g.px = f.px;
  g.py = f.py;
  g.shift = f.shift;
  for (;;) {
    if (f.px) {
      const auto n = static_cast<std::int64_t>(f.lx / cell);
      g.nx = n > 1 ? n : 1;
    } else {
      g.nx = static_cast<std::int64_t>((max_x - min_x) / cell) + 1;
    }
    if (f.py) {
      const auto n = static_cast<std::int64_t>(f.ly / cell);
      g.ny = n > 1 ? n : 1;
    } else {
      g.ny = static_cast<std::int64_t>((max_y - min_y) / cell) + 1;
    }
    if (static_cast<double>(g.nx) * static_cast<double>(g.ny) <= max_cells) break;
    cell *= 1.5;
  }
  g.cell_x = f.px ? f.lx / static_cast<double>(g.nx) : cell;
  g.cell_y = f.py ? f.ly / static_cast<double>(g.ny) : cell;
  g.ox = f.px ? f.x0 : min_x;
  g.oy = f.py ? f.y0 : min_y;
  return g;
}

/// The clamped cell of `v` along a direction that is not periodic.
TRIDEM_HD inline std::int64_t clamped_cell(double v, double origin, double cell, std::int64_t n) {
  const auto c = static_cast<std::int64_t>((v - origin) / cell);
  return c < 0 ? 0 : (c > n - 1 ? n - 1 : c);
}

/// The cell (column + row · nx) of a small particle whose box corner is (lo_x, lo_y).
TRIDEM_HD inline std::int64_t periodic_grid_cell(const PeriodicGrid& g, double lo_x, double lo_y) {
  long long wraps = 0;
  std::int64_t row = 0;
  double x = lo_x;
  if (g.py) {
    row = physics::periodic_cell_of(lo_y, g.oy, g.cell_y, g.ny, wraps);
    x -= static_cast<double>(wraps) * g.shift;  // the image at −wraps periods
  } else {
    row = clamped_cell(lo_y, g.oy, g.cell_y, g.ny);
  }
  const std::int64_t column = g.px ? physics::periodic_cell_of(x, g.ox, g.cell_x, g.nx, wraps)
                                   : clamped_cell(x, g.ox, g.cell_x, g.nx);
  return column + row * g.nx;
}

/// Calls cell(c) for the 3 × 3 cells about the corner (lo_x, lo_y) of a particle binned in
/// `own_cell`, taken modulo the grid along the periodic directions; a row reached across a
/// Lees-Edwards boundary holds images shifted along x, so its three columns are centred on
/// the corner shifted back. A periodic direction of fewer than 3 cells is scanned whole
/// (each cell once).
template <class Cell>
TRIDEM_HD inline void for_each_periodic_neighbour_cell(const PeriodicGrid& g, double lo_x,
                                                       double lo_y, std::int64_t own_cell,
                                                       Cell&& cell) {
  const std::int64_t nx = g.nx, ny = g.ny;
  const bool all_rows = g.py && ny < 3;
  const bool all_columns = g.px && (nx < 3 || all_rows);
  const std::int64_t own_row = own_cell / nx, own_column = own_cell % nx;
  const auto raw_row =
      g.py ? static_cast<std::int64_t>(::floor((lo_y - g.oy) / g.cell_y)) : own_row;
  const std::int64_t row_first = all_rows ? 0 : raw_row - 1;
  const std::int64_t row_last = all_rows ? ny - 1 : raw_row + 1;
  for (std::int64_t r_raw = row_first; r_raw <= row_last; ++r_raw) {
    std::int64_t row = r_raw, wraps = 0;
    if (g.py && !all_rows) {
      wraps = r_raw >= 0 ? r_raw / ny : -((-r_raw + ny - 1) / ny);
      row = r_raw - wraps * ny;
    } else if (!g.py && (row < 0 || row >= ny)) {
      continue;
    }
    std::int64_t col_first = 0, col_last = nx - 1;
    if (!all_columns) {
      const double x = lo_x - static_cast<double>(wraps) * g.shift;
      const auto centre =
          g.px ? static_cast<std::int64_t>(::floor((x - g.ox) / g.cell_x)) : own_column;
      col_first = centre - 1;
      col_last = centre + 1;
    }
    for (std::int64_t c_raw = col_first; c_raw <= col_last; ++c_raw) {
      std::int64_t column = c_raw;
      if (g.px)
        column = ((c_raw % nx) + nx) % nx;
      else if (column < 0 || column >= nx)
        continue;
      cell(column + row * nx);
    }
  }
}

/// Whether box_i (particle i's, centroid ci) overlaps the box of j's nearest image (j's box
/// box_j, centroid cj); in double, with a margin of a few roundings of the period, since
/// the image's box is j's box moved by a period. `sheared_slack` widens the test along x
/// for an image across the Lees-Edwards boundary: the GPU's list, kept over several steps
/// while that image slides, lists such a pair while it is within the slack (0 on the CPU,
/// which finds its pairs every step).
template <class Real>
TRIDEM_HD inline bool periodic_boxes_overlap(const physics::PeriodicFrame& f, Vec2d ci, Vec2d cj,
                                             const physics::Aabb<Real>& box_i,
                                             const physics::Aabb<Real>& box_j,
                                             double sheared_slack = 0) {
  const physics::PeriodicImage im = physics::nearest_image(f, ci, cj);
  if (im.shift.x == 0 && im.shift.y == 0) return physics::boxes_overlap(box_i, box_j);
  const double tol = 8 * DBL_EPSILON * (::fabs(f.lx) + ::fabs(f.ly) + ::fabs(ci.x) + ::fabs(ci.y));
  const double tol_x = im.shift.y != 0 ? tol + sheared_slack : tol;
  const auto d = [](Real v) { return static_cast<double>(v); };
  return d(box_i.lo.x) <= d(box_j.hi.x) + im.shift.x + tol_x &&
         d(box_j.lo.x) + im.shift.x <= d(box_i.hi.x) + tol_x &&
         d(box_i.lo.y) <= d(box_j.hi.y) + im.shift.y + tol &&
         d(box_j.lo.y) + im.shift.y <= d(box_i.hi.y) + tol;
}

}  // namespace tridem
