#include "broadphase/candidate_pairs.hpp"

#include "broadphase/emitter_rule.hpp"
#include "broadphase/grid_rules.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tridem {

GridClasses classify_for_grid(const std::vector<double>& longest_edge,
                              const std::vector<Motion>& motion) {
  double l_free = 0, l_all = 0;
  for (std::size_t i = 0; i < longest_edge.size(); ++i) {
    l_all = std::max(l_all, longest_edge[i]);
    if (motion[i] == Motion::Free) l_free = std::max(l_free, longest_edge[i]);
  }
  GridClasses g;
  g.cell = l_free > 0 ? l_free : l_all;
  g.small.resize(longest_edge.size());
  for (std::size_t i = 0; i < longest_edge.size(); ++i) g.small[i] = longest_edge[i] <= g.cell;
  return g;
}

template <class Real>
CandidatePairs<Real>::CandidatePairs(const std::vector<double>& longest_edge,
                                     const std::vector<Motion>& motion)
    : n_(longest_edge.size()), free_(n_) {
  GridClasses classes = classify_for_grid(longest_edge, motion);
  small_ = std::move(classes.small);
  for (std::size_t i = 0; i < n_; ++i) {
    free_[i] = motion[i] == Motion::Free;
    if (!small_[i]) large_.push_back(static_cast<std::int32_t>(i));
  }
  cell_size_ = static_cast<Real>(classes.cell);
  cell_of_.resize(n_);
  sorted_.resize(n_);
  row_count_.resize(n_);
  // At most 4 cells per particle (see bin), so the grid never allocates during a run.
  cell_start_.resize(4 * n_ + 17);
  cell_count_.resize(4 * n_ + 17);
}

// The small particles' box corners' extent and widest box, which size the grid; zeros when
// none is small. Double, whatever Real: a float corner converts exactly. Min and max give
// the same sum in any order, so the team's extent is the serial one.
template <class Real>
void CandidatePairs<Real>::fold_small_extent(const BoxArrays<Real>& b) {
  const auto n = static_cast<std::int64_t>(n_);
  SmallExtent mine = empty_extent();
#pragma omp for schedule(static) nowait
  for (std::int64_t i = 0; i < n; ++i) {
    if (!small_[i]) continue;
    mine.min_x = std::min(mine.min_x, static_cast<double>(b.lo_x[i]));
    mine.min_y = std::min(mine.min_y, static_cast<double>(b.lo_y[i]));
    mine.max_x = std::max(mine.max_x, static_cast<double>(b.lo_x[i]));
    mine.max_y = std::max(mine.max_y, static_cast<double>(b.lo_y[i]));
    mine.widest = std::max(mine.widest, box_width(b.lo_x[i], b.lo_y[i], b.hi_x[i], b.hi_y[i]));
  }
  team_fold(extent_sum_, mine, [](SmallExtent s, const SmallExtent& m) {
    return SmallExtent{std::min(s.min_x, m.min_x), std::min(s.min_y, m.min_y),
                       std::max(s.max_x, m.max_x), std::max(s.max_y, m.max_y),
                       std::max(s.widest, m.widest)};
  });
}

template <class Real>
typename CandidatePairs<Real>::SmallExtent CandidatePairs<Real>::take_small_extent() {
  const SmallExtent e = extent_sum_;
  extent_sum_ = empty_extent();
  if (e.min_x > e.max_x) return {};
  return e;
}

template <class Real>
void CandidatePairs<Real>::bin(const BoxArrays<Real>& b) {
  const auto n = static_cast<std::int64_t>(n_);
  fold_small_extent(b);
  team_single([&] {
    const SmallExtent e = take_small_extent();
    origin_x_ = static_cast<Real>(e.min_x);
    origin_y_ = static_cast<Real>(e.min_y);
    // At most 4 cells per particle.
    const GridFit fit = fit_grid(e.max_x - e.min_x, e.max_y - e.min_y,
                                 grid_cell_for(static_cast<double>(cell_size_), e.widest),
                                 static_cast<double>(4 * n_ + 16));
    nx_ = fit.nx;
    ny_ = fit.ny;
    grid_cell_ = static_cast<Real>(fit.cell);
  });
#pragma omp for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!small_[i]) continue;
    cell_of_[i] = cell_coordinate(b.lo_x[i], origin_x_, grid_cell_, nx_) +
                  cell_coordinate(b.lo_y[i], origin_y_, grid_cell_, ny_) * nx_;
  }
  team_single([&] { sort_into_cells(nx_ * ny_); });
}

// Counting sort by cell; serial, and in index order within a cell.
template <class Real>
void CandidatePairs<Real>::sort_into_cells(std::int64_t cells) {
  const auto n = static_cast<std::int64_t>(n_);
  std::fill(cell_count_.begin(), cell_count_.begin() + cells, 0);
  for (std::int64_t i = 0; i < n; ++i)
    if (small_[i]) ++cell_count_[cell_of_[i]];
  cell_start_[0] = 0;
  for (std::int64_t c = 0; c < cells; ++c) cell_start_[c + 1] = cell_start_[c] + cell_count_[c];
  std::copy(cell_start_.begin(), cell_start_.begin() + cells, cell_count_.begin());
  for (std::int64_t i = 0; i < n; ++i)
    if (small_[i]) sorted_[cell_count_[cell_of_[i]]++] = static_cast<std::int32_t>(i);
}

// The periodic grid: along a periodic direction the cells tile the period exactly (n cells
// of period/n, no smaller than the grid's cell), and a corner's cell is taken modulo n.
// Across a Lees-Edwards y boundary, a particle whose corner lies past the cell is binned
// as the image that brings it back, shifted along x with it.
template <class Real>
void CandidatePairs<Real>::bin_periodic(const BoxArrays<Real>& b, const PeriodicView& p) {
  const auto n = static_cast<std::int64_t>(n_);
  const physics::PeriodicFrame& f = p.frame;
  fold_small_extent(b);
  team_single([&] {
    const SmallExtent e = take_small_extent();
    double cell = grid_cell_for(static_cast<double>(cell_size_), e.widest);
    const double max_cells = static_cast<double>(4 * n_ + 16);
    for (;;) {
      nx_ = f.px ? std::max<std::int64_t>(1, static_cast<std::int64_t>(f.lx / cell))
                 : static_cast<std::int64_t>((e.max_x - e.min_x) / cell) + 1;
      ny_ = f.py ? std::max<std::int64_t>(1, static_cast<std::int64_t>(f.ly / cell))
                 : static_cast<std::int64_t>((e.max_y - e.min_y) / cell) + 1;
      if (static_cast<double>(nx_) * static_cast<double>(ny_) <= max_cells) break;
      cell *= 1.5;
    }
    cell_x_ = f.px ? f.lx / static_cast<double>(nx_) : cell;
    cell_y_ = f.py ? f.ly / static_cast<double>(ny_) : cell;
    origin_x_ = static_cast<Real>(0);
    origin_y_ = static_cast<Real>(0);
    px_origin_ = f.px ? f.x0 : e.min_x;
    py_origin_ = f.py ? f.y0 : e.min_y;
  });
  const double ox = px_origin_, oy = py_origin_;
#pragma omp for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!small_[i]) continue;
    long long wraps = 0;
    const double lo_x = static_cast<double>(b.lo_x[i]), lo_y = static_cast<double>(b.lo_y[i]);
    std::int64_t row = 0;
    double x = lo_x;
    if (f.py) {
      row = physics::periodic_cell_of(lo_y, oy, cell_y_, ny_, wraps);
      x -= static_cast<double>(wraps) * f.shift;  // the image at −wraps periods
    } else {
      row = std::clamp<std::int64_t>(static_cast<std::int64_t>((lo_y - oy) / cell_y_), 0, ny_ - 1);
    }
    std::int64_t column = 0;
    if (f.px)
      column = physics::periodic_cell_of(x, ox, cell_x_, nx_, wraps);
    else
      column = std::clamp<std::int64_t>(static_cast<std::int64_t>((x - ox) / cell_x_), 0, nx_ - 1);
    cell_of_[i] = column + row * nx_;
  }
  team_single([&] { sort_into_cells(nx_ * ny_); });
}

// Whether i's box overlaps the box of j's nearest image; in double, with a margin of a few
// roundings of the period, since the image's box is i's box moved by a period.
template <class Real>
bool CandidatePairs<Real>::overlaps_periodic(std::int32_t i, std::int32_t j,
                                             const BoxArrays<Real>& b,
                                             const PeriodicView& p) const {
  const physics::PeriodicImage im =
      physics::nearest_image(p.frame, Vec2d{p.x[i], p.y[i]}, Vec2d{p.x[j], p.y[j]});
  if (im.shift.x == 0 && im.shift.y == 0) return physics::boxes_overlap(b.box(i), b.box(j));
  const double tol =
      8 * std::numeric_limits<double>::epsilon() *
      (std::abs(p.frame.lx) + std::abs(p.frame.ly) + std::abs(p.x[i]) + std::abs(p.y[i]));
  const auto d = [](Real v) { return static_cast<double>(v); };
  return d(b.lo_x[i]) <= d(b.hi_x[j]) + im.shift.x + tol &&
         d(b.lo_x[j]) + im.shift.x <= d(b.hi_x[i]) + tol &&
         d(b.lo_y[i]) <= d(b.hi_y[j]) + im.shift.y + tol &&
         d(b.lo_y[j]) + im.shift.y <= d(b.hi_y[i]) + tol;
}

// What both scans share: who emits, all-pairs, the large particles. `overlaps(j)` is the
// box test of i and j, `scan_cells(cell)` calls `cell(c)` for each grid cell to look in.
template <class Real>
template <class Overlaps, class ScanCells, class Visit>
void CandidatePairs<Real>::visit_with(std::int32_t i, Method method, Overlaps&& overlaps,
                                      ScanCells&& scan_cells, Visit&& visit) const {
  const bool free_i = free_[i] != 0;
  // All-pairs has no size classes: every particle counts as small.
  auto consider = [&](std::int32_t j, bool small_j) {
    if (emits_pair(i, j, true, small_j, free_i, free_[j] != 0) && overlaps(j)) visit(j);
  };
  if (method == Method::AllPairs) {
    for (auto j = static_cast<std::int32_t>(i + 1); j < static_cast<std::int32_t>(n_); ++j)
      consider(j, true);
    return;
  }
  if (!small_[i]) return;  // a large particle emits nothing: the small ones reach it
  scan_cells([&](std::int64_t c) {
    for (std::int64_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) consider(sorted_[k], true);
  });
  for (const std::int32_t j : large_) consider(j, false);
}

// The 3 × 3 cells about i's corner, taken modulo the grid along the periodic directions;
// a row reached across a Lees-Edwards boundary holds images shifted along x, so its three
// columns are centred on i's corner shifted back. A periodic direction of fewer than 3
// cells is scanned whole (each cell once).
template <class Real>
template <class Visit>
void CandidatePairs<Real>::visit_periodic(std::int32_t i, const BoxArrays<Real>& b,
                                          const PeriodicView& p, Method method,
                                          Visit&& visit) const {
  const physics::PeriodicFrame& f = p.frame;
  auto overlaps = [&](std::int32_t j) { return overlaps_periodic(i, j, b, p); };
  auto scan_cells = [&](auto&& cell) {
    const double lo_x = static_cast<double>(b.lo_x[i]), lo_y = static_cast<double>(b.lo_y[i]);
    const bool all_rows = f.py && ny_ < 3;
    const bool all_columns = f.px && (nx_ < 3 || all_rows);
    const std::int64_t own_row = cell_of_[i] / nx_, own_column = cell_of_[i] % nx_;
    const auto raw_row =
        f.py ? static_cast<std::int64_t>(std::floor((lo_y - py_origin_) / cell_y_)) : own_row;
    const std::int64_t row_first = all_rows ? 0 : raw_row - 1;
    const std::int64_t row_last = all_rows ? ny_ - 1 : raw_row + 1;
    for (std::int64_t r_raw = row_first; r_raw <= row_last; ++r_raw) {
      std::int64_t row = r_raw, wraps = 0;
      if (f.py && !all_rows) {
        wraps = r_raw >= 0 ? r_raw / ny_ : -((-r_raw + ny_ - 1) / ny_);
        row = r_raw - wraps * ny_;
      } else if (!f.py && (row < 0 || row >= ny_)) {
        continue;
      }
      std::int64_t col_first = 0, col_last = nx_ - 1;
      if (!all_columns) {
        const double x = lo_x - static_cast<double>(wraps) * f.shift;
        const auto centre =
            f.px ? static_cast<std::int64_t>(std::floor((x - px_origin_) / cell_x_)) : own_column;
        col_first = centre - 1;
        col_last = centre + 1;
      }
      for (std::int64_t c_raw = col_first; c_raw <= col_last; ++c_raw) {
        std::int64_t column = c_raw;
        if (f.px)
          column = ((c_raw % nx_) + nx_) % nx_;
        else if (column < 0 || column >= nx_)
          continue;
        cell(column + row * nx_);
      }
    }
  };
  visit_with(i, method, overlaps, scan_cells, visit);
}

template <class Real>
template <class Visit>
void CandidatePairs<Real>::visit_candidates(std::int32_t i, const BoxArrays<Real>& b,
                                            Method method, Visit&& visit) const {
  const physics::Aabb<Real> box_i = b.box(i);
  auto overlaps = [&](std::int32_t j) { return physics::boxes_overlap(box_i, b.box(j)); };
  auto scan_cells = [&](auto&& cell) {
    const std::int64_t cx = cell_of_[i] % nx_, cy = cell_of_[i] / nx_;
    for (std::int64_t y = std::max<std::int64_t>(cy - 1, 0); y <= std::min(cy + 1, ny_ - 1); ++y)
      for (std::int64_t x = std::max<std::int64_t>(cx - 1, 0); x <= std::min(cx + 1, nx_ - 1); ++x)
        cell(x + y * nx_);
  };
  visit_with(i, method, overlaps, scan_cells, visit);
}

template <class Real>
void CandidatePairs<Real>::find(const BoxArrays<Real>& b, Method method, bool parallel,
                                PairList& pairs, const PeriodicView* periodic) {
  on_team(parallel, [&] {
    if (periodic) {
      if (method == Method::Grid) bin_periodic(b, *periodic);
      fill_rows(n_, parallel, row_count_, pairs, [&](std::int32_t i, auto&& emit) {
        visit_periodic(i, b, *periodic, method, emit);
      });
      return;
    }
    if (method == Method::Grid) bin(b);
    fill_rows(n_, parallel, row_count_, pairs,
              [&](std::int32_t i, auto&& emit) { visit_candidates(i, b, method, emit); });
  });
}

template class CandidatePairs<float>;
template class CandidatePairs<double>;

}  // namespace tridem
