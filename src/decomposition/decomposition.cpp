#include "decomposition/decomposition.hpp"

#include "decomposition/periodic_images.hpp"
#include "decomposition/row_cut.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numeric>

namespace tridem {

namespace {

template <class Real>
Hull<Real> empty_hull() {
  return {std::numeric_limits<Real>::max(), std::numeric_limits<Real>::max(),
          std::numeric_limits<Real>::lowest(), std::numeric_limits<Real>::lowest()};
}

/// Rows of a 2D layout when the scene leaves them to us: the sub-domains as square as the
/// extent allows, about twice as many as the particles need at full capacity (the bands
/// take room too). The paper sets its DLy by hand.
int automatic_rows(std::size_t particles, int capacity, std::int64_t cells_x,
                   std::int64_t cells_y) {
  const double domains = std::max(1.0, 2.0 * static_cast<double>(particles) / capacity);
  const double rows = std::sqrt(domains * static_cast<double>(cells_y) /
                                static_cast<double>(std::max<std::int64_t>(cells_x, 1)));
  return static_cast<int>(std::clamp<double>(std::round(rows), 1.0,
                                             static_cast<double>(cells_y)));
}

}  // namespace

template <class Real>
Decomposition<Real>::Decomposition(const DecompositionSettings& settings, double cell,
                                   std::vector<std::uint8_t> small)
    : settings_(settings), cell_(cell), n_(small.size()), small_(std::move(small)) {
  if (settings_.capacity < 2)
    throw SceneError(fmt::format(
        "[simulation.decomposition] capacity = {} cannot hold a particle and a partner: use "
        "at least 2 (the paper uses 256)",
        settings_.capacity));
  if (!(cell_ > 0)) cell_ = 1;  // no small particle has an edge: nothing will be binned
  for (std::size_t p = 0; p < n_; ++p)
    if (!small_[p]) large_.push_back(static_cast<std::int32_t>(p));
  cell_row_.assign(n_, 0);
  cell_col_.assign(n_, 0);
  owner_.assign(n_, -1);
  last_owner_.assign(n_, -1);
  row_begin_ = {kOpenBorder};
  row_first_ = {0, 1};
  col_begin_ = {kOpenBorder};
}

template <class Real>
DomainMap Decomposition<Real>::map() const {
  return {origin_x_,         origin_y_,         cell_, rows(), row_begin_.data(),
          row_first_.data(), col_begin_.data()};
}

template <class Real>
ParticleRange Decomposition<Real>::owned(int k) const {
  return {owned_.data() + owned_offset_[k], owned_.data() + owned_offset_[k + 1]};
}

template <class Real>
ParticleRange Decomposition<Real>::members(int k) const {
  return {members_.data() + member_offset_[k], members_.data() + member_offset_[k + 1]};
}

template <class Real>
void Decomposition<Real>::update(const DomainInput<Real>& in, bool parallel,
                                 const physics::PeriodicFrame* periodic) {
  parallel_ = parallel;
  periodic_ = periodic != nullptr;
  if (periodic_) {
    frame_ = *periodic;
    extent_ = empty_hull<double>();
    for (std::size_t p = 0; p < n_; ++p)
      if (small_[p])
        extent_ = {
            std::min<double>(extent_.lo_x, in.lo_x[p]), std::min<double>(extent_.lo_y, in.lo_y[p]),
            std::max<double>(extent_.hi_x, in.hi_x[p]), std::max<double>(extent_.hi_y, in.hi_y[p])};
  }
  if (started_) compute_cells(in);
  else initial_partition(in);
  assign(in);
  if (stats_.updates > 0)
    for (std::size_t p = 0; p < n_; ++p) stats_.migrations += owner_[p] != last_owner_[p];
  // Each successful move hands an occupied column to a neighbour that stays within the
  // capacity, and a row cut anew fits by construction, so this ends; the bound only
  // guards against a broken invariant.
  const std::size_t bound = 2 * (n_ + static_cast<std::size_t>(count())) + 16;
  for (std::size_t round = 0;; ++round) {
    const int k = first_overflowing();
    if (k < 0) break;
    if (round > bound)
      throw RunError("internal error: the domain decomposition did not settle its borders");
    ++stats_.overflows;
    if (move_border(k, in)) {
      ++stats_.border_moves;
    } else {
      index_rows();
      partition_row(row_of_domain(k), in);
      ++stats_.repartitions;
    }
    assign(in);
  }
  last_owner_ = owner_;
  for (int k = 0; k < count(); ++k) stats_.max_members = std::max(stats_.max_members, staged(k));
  ++stats_.updates;
}

template <class Real>
void Decomposition<Real>::compute_cells(const DomainInput<Real>& in) {
  const auto n = static_cast<std::int64_t>(n_);
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::int64_t p = 0; p < n; ++p) {
    if (!small_[p]) continue;
    cell_col_[p] = decomposition_cell(static_cast<double>(in.x[p]), origin_x_, cell_);
    cell_row_[p] = decomposition_cell(static_cast<double>(in.y[p]), origin_y_, cell_);
  }
}

template <class Real>
void Decomposition<Real>::initial_partition(const DomainInput<Real>& in) {
  started_ = true;
  double min_x = std::numeric_limits<double>::max(), min_y = min_x;
  double max_x = std::numeric_limits<double>::lowest(), max_y = max_x;
  std::size_t small = 0;
  for (std::size_t p = 0; p < n_; ++p) {
    if (!small_[p]) continue;
    ++small;
    min_x = std::min(min_x, static_cast<double>(in.x[p]));
    min_y = std::min(min_y, static_cast<double>(in.y[p]));
    max_x = std::max(max_x, static_cast<double>(in.x[p]));
    max_y = std::max(max_y, static_cast<double>(in.y[p]));
  }
  if (small == 0) return;  // one sub-domain, nothing to stage
  origin_x_ = min_x;
  origin_y_ = min_y;
  compute_cells(in);
  const std::int64_t cells_x = decomposition_cell(max_x, origin_x_, cell_) + 1;
  const std::int64_t cells_y = decomposition_cell(max_y, origin_y_, cell_) + 1;
  int rows = 1;
  if (settings_.layout == DecompositionLayout::Grid)
    rows = settings_.rows > 0 ? settings_.rows
                              : automatic_rows(small, settings_.capacity, cells_x, cells_y);
  // Rows of equal height DLy over the centroids (the paper's fixed DLy); the first and last
  // stay open, for particles that leave the extent.
  const std::int64_t height = (cells_y + rows - 1) / rows;
  row_begin_.assign(1, kOpenBorder);
  for (int r = 1; r < rows; ++r) row_begin_.push_back(r * height);
  row_first_.resize(static_cast<std::size_t>(rows) + 1);
  std::iota(row_first_.begin(), row_first_.end(), 0);
  col_begin_.assign(static_cast<std::size_t>(rows), kOpenBorder);
  index_rows();
  for (int r = 0; r < rows; ++r) partition_row(r, in);
}

template <class Real>
void Decomposition<Real>::assign(const DomainInput<Real>& in) {
  const DomainMap m = map();
  const int domains = count();
  const auto n = static_cast<std::int64_t>(n_);
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::int64_t p = 0; p < n; ++p)
    if (small_[p]) owner_[p] = m.owner(cell_row_[p], cell_col_[p]);
  // Owned lists: a counting sort by owner, ascending particles within each.
  owned_offset_.assign(static_cast<std::size_t>(domains) + 1, 0);
  for (std::int64_t p = 0; p < n; ++p)
    if (small_[p]) ++owned_offset_[owner_[p] + 1];
  std::partial_sum(owned_offset_.begin(), owned_offset_.end(), owned_offset_.begin());
  owned_.resize(static_cast<std::size_t>(owned_offset_.back()));
  cursor_.assign(owned_offset_.begin(), owned_offset_.end() - 1);
  for (std::int64_t p = 0; p < n; ++p)
    if (small_[p]) owned_[cursor_[owner_[p]]++] = static_cast<std::int32_t>(p);
  // The boxes in owned order: the scans below then read memory in sequence.
  const auto owned_count = static_cast<std::int64_t>(owned_.size());
  owned_box_.resize(owned_.size());
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::int64_t o = 0; o < owned_count; ++o) {
    const std::int32_t p = owned_[o];
    owned_box_[o] = {in.lo_x[p], in.lo_y[p], in.hi_x[p], in.hi_y[p]};
  }
  hull_.resize(static_cast<std::size_t>(domains));
#pragma omp parallel for schedule(static) if (parallel_)
  for (int k = 0; k < domains; ++k) {
    Hull<Real> h = empty_hull<Real>();
    for (auto o = owned_offset_[k]; o < owned_offset_[k + 1]; ++o) {
      const Hull<Real>& b = owned_box_[o];
      h = {std::min(h.lo_x, b.lo_x), std::min(h.lo_y, b.lo_y), std::max(h.hi_x, b.hi_x),
           std::max(h.hi_y, b.hi_y)};
    }
    hull_[k] = h;
  }
  // Overlap bands: the particles whose boxes reach the hull, looked for among those owned
  // by the sub-domains near this one (kReachCells), each sub-domain on its own.
  if (staged_.size() < static_cast<std::size_t>(domains))
    staged_.resize(static_cast<std::size_t>(domains));
#pragma omp parallel for schedule(dynamic, 8) if (parallel_)
  for (int k = 0; k < domains; ++k) {
    std::vector<std::int32_t>& staged = staged_[k];
    staged.clear();
    if (owned_offset_[k] == owned_offset_[k + 1]) continue;  // empty hull: stages nothing
    const Hull<Real>& h = hull_[k];
    visit_neighbours(k, [&](int q) {
      for (auto o = owned_offset_[q]; o < owned_offset_[q + 1]; ++o) {
        const Hull<Real>& b = owned_box_[o];
        if (box_reaches(b.lo_x, b.lo_y, b.hi_x, b.hi_y, h)) staged.push_back(owned_[o]);
      }
    });
    if (periodic_) stage_images(h, staged);
    std::sort(staged.begin(), staged.end());
    // A particle can reach the hull as itself and as an image: it is staged once.
    if (periodic_) staged.erase(std::unique(staged.begin(), staged.end()), staged.end());
  }
  member_offset_.resize(static_cast<std::size_t>(domains) + 1);
  member_offset_[0] = 0;
  for (int k = 0; k < domains; ++k)
    member_offset_[k + 1] = member_offset_[k] + static_cast<std::int32_t>(staged_[k].size());
  members_.resize(static_cast<std::size_t>(member_offset_.back()));
#pragma omp parallel for schedule(static) if (parallel_)
  for (int k = 0; k < domains; ++k)
    std::copy(staged_[k].begin(), staged_[k].end(), members_.begin() + member_offset_[k]);
}

template <class Real>
template <class Visit>
void Decomposition<Real>::visit_neighbours(int k, Visit&& visit) const {
  // Cells of sub-domain k, widened by kReachCells; the open ends stay open.
  auto below = [](std::int64_t c) { return c == kOpenBorder ? c : c - kReachCells; };
  auto above = [](std::int64_t c) { return c == kOpenEnd ? c : c + kReachCells; };
  const DomainMap m = map();
  const int r = row_of_domain(k);
  const std::int64_t row_hi = r + 1 < rows() ? row_begin_[r + 1] - 1 : kOpenEnd;
  const std::int64_t col_hi = k + 1 < row_first_[r + 1] ? col_begin_[k + 1] - 1 : kOpenEnd;
  const int r_end = m.row_of(above(row_hi));
  for (int rr = m.row_of(below(row_begin_[r])); rr <= r_end; ++rr) {
    const int q_end = m.in_row(rr, above(col_hi));
    for (int q = m.in_row(rr, below(col_begin_[k])); q <= q_end; ++q) visit(q);
  }
}

template <class Real>
void Decomposition<Real>::stage_images(const Hull<Real>& h,
                                       std::vector<std::int32_t>& staged) const {
  const double tol = image_margin(frame_, h.lo_x, h.lo_y, h.hi_x, h.hi_y);
  const double lo_x = h.lo_x - tol, lo_y = h.lo_y - tol, hi_x = h.hi_x + tol, hi_y = h.hi_y + tol;
  const DomainMap m = map();
  for_each_image(frame_, extent_, lo_x, lo_y, hi_x, hi_y, [&](double sx, double sy) {
    // The particles whose boxes moved by (sx, sy) reach the hull: those whose boxes reach
    // the hull moved back. Their centroids lie within a cell of it (kReachCells).
    const double rlo_x = lo_x - sx, rhi_x = hi_x - sx, rlo_y = lo_y - sy, rhi_y = hi_y - sy;
    const int r_end = m.row_of(decomposition_cell(rhi_y, origin_y_, cell_) + kReachCells);
    const std::int64_t c_lo = decomposition_cell(rlo_x, origin_x_, cell_) - kReachCells;
    const std::int64_t c_hi = decomposition_cell(rhi_x, origin_x_, cell_) + kReachCells;
    for (int rr = m.row_of(decomposition_cell(rlo_y, origin_y_, cell_) - kReachCells); rr <= r_end;
         ++rr) {
      const int q_end = m.in_row(rr, c_hi);
      for (int q = m.in_row(rr, c_lo); q <= q_end; ++q)
        for (auto o = owned_offset_[q]; o < owned_offset_[q + 1]; ++o) {
          const Hull<Real>& b = owned_box_[o];
          if (image_reaches(frame_, h, b.lo_x, b.lo_y, b.hi_x, b.hi_y, sx, sy))
            staged.push_back(owned_[o]);
        }
    }
  });
}

template <class Real>
void Decomposition<Real>::add_image_bands(Real y_lo, Real y_hi, const DomainInput<Real>& in,
                                          BandCounter<Real>& band) const {
  const double tol = image_margin(frame_, extent_.lo_x, extent_.lo_y, extent_.hi_x, extent_.hi_y);
  // Every image that brings some box onto the row's y-extent, over the whole cell along x:
  // the row's own band moved along x, and the boxes near the other side of a y boundary.
  const std::size_t own = band.lo.size();
  for_each_image(frame_, extent_, extent_.lo_x - tol, y_lo - tol, extent_.hi_x + tol, y_hi + tol,
                 [&](double sx, double sy) {
                   auto add = [&](double lo, double hi) {
                     band.lo.push_back(static_cast<Real>(lo + sx));
                     band.hi.push_back(static_cast<Real>(hi + sx));
                   };
                   if (sy == 0) {
                     for (std::size_t e = 0; e < own; ++e) add(band.lo[e], band.hi[e]);
                     return;
                   }
                   for (std::size_t p = 0; p < n_; ++p)
                     if (small_[p] && in.lo_y[p] + sy <= y_hi + tol &&
                         in.hi_y[p] + sy >= y_lo - tol)
                       add(in.lo_x[p], in.hi_x[p]);
                 });
}

template <class Real>
void Decomposition<Real>::index_rows() {
  const DomainMap m = map();
  const int row_count = rows();
  by_row_offset_.assign(static_cast<std::size_t>(row_count) + 1, 0);
  for (std::size_t p = 0; p < n_; ++p)
    if (small_[p]) ++by_row_offset_[m.row_of(cell_row_[p]) + 1];
  std::partial_sum(by_row_offset_.begin(), by_row_offset_.end(), by_row_offset_.begin());
  by_row_.resize(static_cast<std::size_t>(by_row_offset_.back()));
  cursor_.assign(by_row_offset_.begin(), by_row_offset_.end() - 1);
  for (std::size_t p = 0; p < n_; ++p)
    if (small_[p]) by_row_[cursor_[m.row_of(cell_row_[p])]++] = static_cast<std::int32_t>(p);
}

std::string decomposition_summary(const DecompositionStats& s, int sub_domains, int rows,
                                  int capacity) {
  return fmt::format(
      "decomposition: {} sub-domains in {} row{}, at most {} of {} particles staged in one; "
      "{} migrations, {} overflows, {} border moves, {} rows re-cut in {} updates",
      sub_domains, rows, rows == 1 ? "" : "s", s.max_members, capacity, s.migrations,
      s.overflows, s.border_moves, s.repartitions, s.updates);
}

template <class Real>
std::string Decomposition<Real>::summary() const {
  return decomposition_summary(stats_, count(), rows(), settings_.capacity);
}

template <class Real>
int Decomposition<Real>::first_overflowing() const {
  for (int k = 0; k < count(); ++k)
    if (staged(k) > settings_.capacity) return k;
  return -1;
}

template <class Real>
int Decomposition<Real>::row_of_domain(int k) const {
  return static_cast<int>(std::upper_bound(row_first_.begin(), row_first_.end(), k) -
                          row_first_.begin()) - 1;
}

template <class Real>
bool Decomposition<Real>::move_border(int k, const DomainInput<Real>& in) {
  const int r = row_of_domain(k);
  std::int64_t min_col = std::numeric_limits<std::int64_t>::max();
  std::int64_t max_col = std::numeric_limits<std::int64_t>::lowest();
  for (const std::int32_t p : owned(k)) {
    min_col = std::min(min_col, cell_col_[p]);
    max_col = std::max(max_col, cell_col_[p]);
  }
  if (min_col >= max_col) return false;  // one occupied column: nothing to hand over
  // Hand the first occupied column to the left neighbour, or the last to the right one,
  // trying the one that stages fewer particles first; keep the move only if the neighbour
  // still fits.
  struct Move {
    int neighbour, border;
    std::int64_t column;
  };
  Move moves[2];
  int n_moves = 0;
  if (k > row_first_[r]) moves[n_moves++] = {k - 1, k, min_col + 1};
  if (k + 1 < row_first_[r + 1]) moves[n_moves++] = {k + 1, k + 1, max_col};
  if (n_moves == 2 && staged(moves[1].neighbour) < staged(moves[0].neighbour))
    std::swap(moves[0], moves[1]);
  for (int i = 0; i < n_moves; ++i) {
    const Move& m = moves[i];
    const std::int64_t saved = col_begin_[m.border];
    col_begin_[m.border] = m.column;
    assign(in);
    if (staged(m.neighbour) <= settings_.capacity) return true;
    col_begin_[m.border] = saved;
  }
  return false;
}

template <class Real>
void Decomposition<Real>::partition_row(int r, const DomainInput<Real>& in) {
  std::vector<std::int32_t>& ps = row_particles_;
  ps.assign(by_row_.begin() + by_row_offset_[r], by_row_.begin() + by_row_offset_[r + 1]);
  Real y_lo = std::numeric_limits<Real>::max(), y_hi = std::numeric_limits<Real>::lowest();
  for (const std::int32_t p : ps) {
    y_lo = std::min(y_lo, in.lo_y[p]);
    y_hi = std::max(y_hi, in.hi_y[p]);
  }
  RowCut cut;
  if (!ps.empty()) {
    std::stable_sort(ps.begin(), ps.end(),
                     [this](std::int32_t a, std::int32_t b) { return cell_col_[a] < cell_col_[b]; });
    RowColumns<Real> columns;
    for (const std::int32_t p : ps) {
      if (columns.column.empty() || columns.column.back() != cell_col_[p]) {
        columns.column.push_back(cell_col_[p]);
        columns.count.push_back(0);
        columns.lo_x.push_back(in.lo_x[p]);
        columns.hi_x.push_back(in.hi_x[p]);
      }
      ++columns.count.back();
      columns.lo_x.back() = std::min(columns.lo_x.back(), in.lo_x[p]);
      columns.hi_x.back() = std::max(columns.hi_x.back(), in.hi_x[p]);
    }
    // Every box that reaches the row's y-extent may join a band of the row; such a box
    // has its centroid within kReachCells of the row's cells.
    BandCounter<Real> band;
    const DomainMap m = map();
    const std::int64_t lo_row = row_begin_[r] == kOpenBorder ? kOpenBorder
                                                              : row_begin_[r] - kReachCells;
    const std::int64_t hi_row =
        r + 1 < rows() ? row_begin_[r + 1] - 1 + kReachCells : kOpenEnd;
    for (int rr = m.row_of(lo_row); rr <= m.row_of(hi_row); ++rr)
      for (auto at = by_row_offset_[rr]; at < by_row_offset_[rr + 1]; ++at) {
        const std::int32_t p = by_row_[at];
        if (in.lo_y[p] > y_hi || in.hi_y[p] < y_lo) continue;
        band.lo.push_back(in.lo_x[p]);
        band.hi.push_back(in.hi_x[p]);
      }
    if (periodic_) add_image_bands(y_lo, y_hi, in, band);
    std::sort(band.lo.begin(), band.lo.end());
    std::sort(band.hi.begin(), band.hi.end());
    cut = cut_row(columns, band, settings_.columns, settings_.capacity);
    if (cut.overfull >= 0) {
      const auto c = static_cast<double>(columns.column[static_cast<std::size_t>(cut.overfull)]);
      const bool two_d = settings_.layout == DecompositionLayout::Grid;
      throw RunError(fmt::format(
          "domain decomposition: the particles centred in cell column {} (x from {:.6g} to "
          "{:.6g} m{}) stage {} particles with their overlap band, more than the capacity "
          "{} of one sub-domain: raise [simulation.decomposition] capacity, {}, or use "
          "method = \"grid\"",
          static_cast<long long>(c), origin_x_ + c * cell_, origin_x_ + (c + 1) * cell_,
          two_d ? fmt::format(", row {} of {}", r, rows()) : std::string(), cut.overfull_count,
          settings_.capacity,
          two_d ? "use more rows (rows = ...)" : "use layout = \"2d\" to cut it along y"));
    }
  }
  // The row's sub-domains become the cut's.
  const int first = row_first_[r], last = row_first_[r + 1];
  col_begin_.erase(col_begin_.begin() + first + 1, col_begin_.begin() + last);
  col_begin_.insert(col_begin_.begin() + first + 1, cut.starts.begin(), cut.starts.end());
  const int delta = static_cast<int>(cut.starts.size()) + 1 - (last - first);
  for (std::size_t rr = static_cast<std::size_t>(r) + 1; rr < row_first_.size(); ++rr)
    row_first_[rr] += delta;
}

template class Decomposition<float>;
template class Decomposition<double>;

}  // namespace tridem
