#pragma once
// The rules of the domain decomposition that the host bookkeeping and the GPU kernels
// share: which cell a coordinate falls in, which sub-domain owns a cell, and which
// sub-domains a particle's box can reach. Plain arrays, so that the device reads the same
// borders the host computed.
//
// Cells have the size L of the cell grid (classify_for_grid). Rows are bands of cell rows
// along y (one row in 1D); each row is split along x into sub-domains owning runs of cell
// columns. The first row and the first sub-domain of each row start at -infinity, the
// last end at +infinity, so every centroid has an owner wherever it goes.
#include "physics/geometry.hpp"
#include "tridem/hd.hpp"

#include <cstdint>

namespace tridem {

/// Start of the first row / sub-domain of a row: below every cell.
constexpr std::int64_t kOpenBorder = INT64_MIN;
/// End of the last row / sub-domain of a row: above every cell.
constexpr std::int64_t kOpenEnd = INT64_MAX;

/// Cell index of coordinate v: floor((v - origin) / cell), computed in double so that
/// every backend and precision finds the same cell. Clamped well inside int64 (a NaN gives
/// 0: the runaway check stops such a run before its cells matter).
TRIDEM_HD inline std::int64_t decomposition_cell(double v, double origin, double cell) {
  double c = floor((v - origin) / cell);
  constexpr double kFar = 4.0e18;
  if (c != c) return 0;
  c = c < -kFar ? -kFar : (c > kFar ? kFar : c);
  return static_cast<std::int64_t>(c);
}

/// The last index k in [first, last) with begin[k] <= c; begin[first] must be
/// kOpenBorder, so there is always one.
TRIDEM_HD inline int last_starting_at_or_before(const std::int64_t* begin, int first, int last,
                                                std::int64_t c) {
  int lo = first, hi = last;  // begin[lo] <= c < begin[hi] (begin[last] taken as +inf)
  while (hi - lo > 1) {
    const int mid = lo + (hi - lo) / 2;
    if (begin[mid] <= c) lo = mid;
    else hi = mid;
  }
  return lo;
}

/// The bounding box of the boxes a sub-domain owns: a particle whose box overlaps it may
/// be the partner of an owned emitter, so it is staged with the sub-domain (its overlap
/// band). Empty: lo = +max, hi = lowest, which no box reaches.
template <class Real>
struct Hull {
  Real lo_x, lo_y, hi_x, hi_y;
};

template <class Real>
TRIDEM_HD inline bool box_reaches(Real lo_x, Real lo_y, Real hi_x, Real hi_y,
                                  const Hull<Real>& h) {
  return physics::boxes_overlap(physics::box_of(lo_x, lo_y, hi_x, hi_y),
                                physics::box_of(h.lo_x, h.lo_y, h.hi_x, h.hi_y));
}

/// How far (in cells) a partner's centroid can be from an owned emitter's. A box is at
/// most L wide and its centroid lies at most 2/3 of its width from any side, so two
/// overlapping boxes have centroids within 4L/3 < 2L on each axis: two cells.
constexpr std::int64_t kReachCells = 2;

/// The borders of every sub-domain, as the kernels read them.
struct DomainMap {
  double origin_x, origin_y, cell;
  int rows;
  const std::int64_t* row_begin;  ///< first cell row of each row; [0] = kOpenBorder
  const int* row_first;           ///< first sub-domain of each row; rows + 1 entries
  const std::int64_t* col_begin;  ///< first cell column of each sub-domain

  TRIDEM_HD int row_of(std::int64_t cell_row) const {
    return last_starting_at_or_before(row_begin, 0, rows, cell_row);
  }
  TRIDEM_HD int in_row(int row, std::int64_t cell_column) const {
    return last_starting_at_or_before(col_begin, row_first[row], row_first[row + 1],
                                      cell_column);
  }
  /// The sub-domain owning the cell of a centroid.
  TRIDEM_HD int owner(std::int64_t cell_row, std::int64_t cell_column) const {
    return in_row(row_of(cell_row), cell_column);
  }
  /// The row holding sub-domain k.
  TRIDEM_HD int row_holding(int k) const {
    int lo = 0, hi = rows;  // row_first[lo] <= k < row_first[hi]
    while (hi - lo > 1) {
      const int mid = lo + (hi - lo) / 2;
      if (row_first[mid] <= k)
        lo = mid;
      else
        hi = mid;
    }
    return lo;
  }
  /// Whether visit_near(cell_row, cell_column, ...) visits sub-domain k.
  TRIDEM_HD bool near(std::int64_t cell_row, std::int64_t cell_column, int k) const {
    const int r = row_holding(k);
    if (r < row_of(cell_row - kReachCells) || r > row_of(cell_row + kReachCells)) return false;
    return k >= in_row(r, cell_column - kReachCells) && k <= in_row(r, cell_column + kReachCells);
  }
  /// Calls visit(k) for every sub-domain that owns a cell within kReachCells of the
  /// centroid's cell: the only ones whose hull the particle's box can reach. Ascending k.
  template <class Visit>
  TRIDEM_HD void visit_near(std::int64_t cell_row, std::int64_t cell_column,
                            Visit&& visit) const {
    const int r_end = row_of(cell_row + kReachCells);
    for (int r = row_of(cell_row - kReachCells); r <= r_end; ++r) {
      const int k_end = in_row(r, cell_column + kReachCells);
      for (int k = in_row(r, cell_column - kReachCells); k <= k_end; ++k) visit(k);
    }
  }
};

}  // namespace tridem
