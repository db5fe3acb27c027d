#include "broadphase/candidate_pairs.hpp"

#include "broadphase/emitter_rule.hpp"
#include "broadphase/grid_rules.hpp"
#include "broadphase/periodic_grid.hpp"

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

// The periodic grid (broadphase/periodic_grid.hpp: the GPU's builder bins by the same rules).
template <class Real>
void CandidatePairs<Real>::bin_periodic(const BoxArrays<Real>& b, const PeriodicView& p) {
  const auto n = static_cast<std::int64_t>(n_);
  fold_small_extent(b);
  team_single([&] {
    const SmallExtent e = take_small_extent();
    periodic_grid_ = fit_periodic_grid(p.frame, e.min_x, e.min_y, e.max_x, e.max_y,
                                       grid_cell_for(static_cast<double>(cell_size_), e.widest),
                                       static_cast<double>(4 * n_ + 16));
    nx_ = periodic_grid_.nx;
    ny_ = periodic_grid_.ny;
    origin_x_ = static_cast<Real>(0);
    origin_y_ = static_cast<Real>(0);
  });
#pragma omp for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!small_[i]) continue;
    cell_of_[i] = periodic_grid_cell(periodic_grid_, static_cast<double>(b.lo_x[i]),
                                     static_cast<double>(b.lo_y[i]));
  }
  team_single([&] { sort_into_cells(nx_ * ny_); });
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

// The 3 × 3 cells about i's corner, modulo the grid (for_each_periodic_neighbour_cell), and
// the box test against the partner's nearest image (periodic_boxes_overlap).
template <class Real>
template <class Visit>
void CandidatePairs<Real>::visit_periodic(std::int32_t i, const BoxArrays<Real>& b,
                                          const PeriodicView& p, Method method,
                                          Visit&& visit) const {
  const Vec2d ci{p.x[i], p.y[i]};
  const physics::Aabb<Real> box_i = b.box(i);
  auto overlaps = [&](std::int32_t j) {
    return periodic_boxes_overlap(p.frame, ci, Vec2d{p.x[j], p.y[j]}, box_i, b.box(j));
  };
  auto scan_cells = [&](auto&& cell) {
    for_each_periodic_neighbour_cell(periodic_grid_, static_cast<double>(b.lo_x[i]),
                                     static_cast<double>(b.lo_y[i]), cell_of_[i], cell);
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
