#pragma once
// The cell-grid rules every backend bins by, on the host and the device alike.
#include "tridem/hd.hpp"

#include <cstdint>

namespace tridem {

struct GridFit {
  double cell;
  std::int64_t nx, ny;
};

/// Cells of size `cell` over a w_x × w_y extent of corners; a particle thrown far away
/// must not make the grid huge, so past `max_cells` the cells grow instead (more
/// candidates, same pairs).
TRIDEM_HD inline GridFit fit_grid(double wx, double wy, double cell, double max_cells) {
  for (;;) {
    const auto nx = static_cast<std::int64_t>(wx / cell) + 1;
    const auto ny = static_cast<std::int64_t>(wy / cell) + 1;
    if (static_cast<double>(nx) * static_cast<double>(ny) <= max_cells) return {cell, nx, ny};
    cell *= 1.5;
  }
}

/// The wider side of a box, in double (exact for two floats of one box).
template <class Real>
TRIDEM_HD inline double box_width(Real lo_x, Real lo_y, Real hi_x, Real hi_y) {
  const double wx = static_cast<double>(hi_x) - static_cast<double>(lo_x);
  const double wy = static_cast<double>(hi_y) - static_cast<double>(lo_y);
  return wx > wy ? wx : wy;
}

/// The cell a grid needs: a 3x3 scan finds every overlapping pair only if no box is wider
/// than a cell. A box is at most the longest edge L wide in exact arithmetic; boxes
/// rounded outward (mixed precision: float boxes far from the origin are coarse) can be
/// wider, so the widest box of the build sets the cell when it exceeds L, and the
/// division below is rounded by one part in 2^20 in the grid's favour.
TRIDEM_HD inline double grid_cell_for(double cell, double widest) {
  return (widest > cell ? widest : cell) * (1.0 + 0x1p-20);
}

/// The cell column (or row) of a corner at `lo`, clamped to the grid's n cells.
template <class Real>
TRIDEM_HD inline std::int64_t cell_coordinate(Real lo, Real origin, Real cell, std::int64_t n) {
  const auto c = static_cast<std::int64_t>((lo - origin) / cell);
  return c < 0 ? 0 : (c > n - 1 ? n - 1 : c);
}

}  // namespace tridem
