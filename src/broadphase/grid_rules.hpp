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

/// The cell column (or row) of a corner at `lo`, clamped to the grid's n cells.
template <class Real>
TRIDEM_HD inline std::int64_t cell_coordinate(Real lo, Real origin, Real cell, std::int64_t n) {
  const auto c = static_cast<std::int64_t>((lo - origin) / cell);
  return c < 0 ? 0 : (c > n - 1 ? n - 1 : c);
}

}  // namespace tridem
