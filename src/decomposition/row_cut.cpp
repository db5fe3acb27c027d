#include "decomposition/row_cut.hpp"

#include <algorithm>

namespace tridem {

template <class Real>
int BandCounter<Real>::reaching(Real lx, Real hx) const {
  const auto starting = std::upper_bound(lo.begin(), lo.end(), hx) - lo.begin();
  const auto ended = std::lower_bound(hi.begin(), hi.end(), lx) - hi.begin();
  return static_cast<int>(starting - ended);
}

namespace {

/// Staged particles of each sub-domain of a cut; the largest over all.
template <class Real>
int largest_staged(const RowColumns<Real>& row, const BandCounter<Real>& band,
                   const std::vector<std::int64_t>& starts) {
  int largest = 0;
  std::size_t next = 0;
  Real lx = 0, hx = 0;
  bool open = false;
  auto close = [&] {
    if (open) largest = std::max(largest, band.reaching(lx, hx));
    open = false;
  };
  for (std::size_t g = 0; g < row.column.size(); ++g) {
    if (next < starts.size() && row.column[g] >= starts[next]) {
      close();
      ++next;
    }
    lx = open ? std::min(lx, row.lo_x[g]) : row.lo_x[g];
    hx = open ? std::max(hx, row.hi_x[g]) : row.hi_x[g];
    open = true;
  }
  close();
  return largest;
}

template <class Real>
std::vector<std::int64_t> equal_counts(const RowColumns<Real>& row, int columns) {
  long long total = 0;
  for (const int c : row.count) total += c;
  std::vector<std::int64_t> starts;
  long long seen = 0;
  for (std::size_t g = 0; g < row.column.size(); ++g) {
    // Column g starts sub-domain k + 1 once k + 1 shares of the particles lie before it.
    const auto k = static_cast<long long>(starts.size());
    if (g > 0 && k + 1 < columns && seen * columns >= (k + 1) * total)
      starts.push_back(row.column[g]);
    seen += row.count[g];
  }
  return starts;
}

}  // namespace

template <class Real>
RowCut cut_row(const RowColumns<Real>& row, const BandCounter<Real>& band, int columns,
               int capacity) {
  RowCut cut;
  if (columns > 1) {
    cut.starts = equal_counts(row, columns);
    if (largest_staged(row, band, cut.starts) <= capacity) return cut;
    cut.starts.clear();
  }
  Real lx = 0, hx = 0;
  bool open = false;
  for (std::size_t g = 0; g < row.column.size(); ++g) {
    if (open) {
      const Real wider_lo = std::min(lx, row.lo_x[g]), wider_hi = std::max(hx, row.hi_x[g]);
      if (band.reaching(wider_lo, wider_hi) <= capacity) {
        lx = wider_lo;
        hx = wider_hi;
        continue;
      }
      cut.starts.push_back(row.column[g]);
    }
    lx = row.lo_x[g];
    hx = row.hi_x[g];
    open = true;
    const int alone = band.reaching(lx, hx);
    if (alone > capacity) {
      cut.overfull = static_cast<int>(g);
      cut.overfull_count = alone;
      return cut;
    }
  }
  return cut;
}

template struct BandCounter<float>;
template struct BandCounter<double>;
template RowCut cut_row(const RowColumns<float>&, const BandCounter<float>&, int, int);
template RowCut cut_row(const RowColumns<double>&, const BandCounter<double>&, int, int);

}  // namespace tridem
