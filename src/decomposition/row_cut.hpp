#pragma once
// Where to cut one row of cells into sub-domains: the paper's Fig. 17. Walking the
// occupied cell columns from the left, a sub-domain takes columns while its particles,
// overlap band included, stay within the capacity; the next column starts a new one.
#include <cstdint>
#include <vector>

namespace tridem {

/// The particles a row owns, grouped by the cell column of their centroids.
template <class Real>
struct RowColumns {
  std::vector<std::int64_t> column;  ///< occupied cell columns, ascending
  std::vector<int> count;            ///< particles owned in each
  std::vector<Real> lo_x, hi_x;      ///< x-extent of their boxes
};

/// Counts the boxes that reach an x-interval: the particles a sub-domain with that hull
/// would stage. Holds the sorted box ends of every particle near the row (in 2D, those
/// whose boxes reach the row's y-extent: an upper bound of what a sub-domain stages).
template <class Real>
struct BandCounter {
  std::vector<Real> lo, hi;  ///< sorted

  /// Boxes with lo <= hx and hi >= lx, for lx <= hx: every box that ends before lx also
  /// starts before hx, so this is a difference of two counts.
  int reaching(Real lx, Real hx) const;
};

/// The result of a cut: the first column of every sub-domain after the row's first, or
/// the column (an index into RowColumns) that alone stages more than the capacity.
struct RowCut {
  std::vector<std::int64_t> starts;
  int overfull = -1;
  int overfull_count = 0;
};

/// `columns` > 0 asks for that many sub-domains with equal owned counts; where one of
/// them would exceed the capacity, or with `columns` = 0, the row is cut as late as the
/// capacity allows (the fewest sub-domains).
template <class Real>
RowCut cut_row(const RowColumns<Real>& row, const BandCounter<Real>& band, int columns,
               int capacity);

}  // namespace tridem
