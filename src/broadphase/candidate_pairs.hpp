#pragma once
// The broad phase: pairs whose bounding boxes overlap, found with a uniform cell grid.
//
// Cells have the size L of the longest edge among the "small" particles (every free one),
// and a small particle is binned by the lower-left corner of its bounding box: two boxes no
// wider than L that overlap then have corners in neighbouring cells, so a 3×3 scan finds
// them. Boundary triangles larger than L (walls, hopper sides) are kept in a short list
// that every small particle checks directly. Who emits a pair is broadphase/emitter_rule.hpp.
#include "broadphase/default_init_allocator.hpp"
#include "broadphase/pair_list.hpp"
#include "broadphase/periodic_grid.hpp"
#include "physics/geometry.hpp"
#include "physics/periodic_frame.hpp"
#include "tridem/scene.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace tridem {

/// Which particles the grid bins ("small": longest edge at most L) and the cell size L:
/// the longest edge among free particles, or among all when none is free. Every backend
/// bins by this rule.
struct GridClasses {
  double cell = 0;
  std::vector<std::uint8_t> small;
};
GridClasses classify_for_grid(const std::vector<double>& longest_edge,
                              const std::vector<Motion>& motion);

template <class Real>
struct BoxArrays {
  const Real* lo_x;
  const Real* lo_y;
  const Real* hi_x;
  const Real* hi_y;

  physics::Aabb<Real> box(std::int64_t i) const {
    return physics::box_of(lo_x[i], lo_y[i], hi_x[i], hi_y[i]);
  }
};

/// Periodic boundaries (physics/periodic_frame.hpp): the cell at this step and the
/// centroids, from which each pair takes its partner's nearest image.
struct PeriodicView {
  physics::PeriodicFrame frame;
  const double* x;
  const double* y;
};

/// The frame of a scene's periodic cell at time t.
inline physics::PeriodicFrame periodic_frame_of(const PeriodicCell& cell, double t) {
  const PeriodicRange x = cell.x.value_or(PeriodicRange{}), y = cell.y.value_or(PeriodicRange{});
  return physics::periodic_frame_at(cell.x.has_value(), x.lo, x.length(), cell.y.has_value(), y.lo,
                                    y.length(), cell.shear_rate, t);
}

template <class Real>
class CandidatePairs {
 public:
  /// `longest_edge` and `motion` are per particle; they fix which particles are small.
  CandidatePairs(const std::vector<double>& longest_edge, const std::vector<Motion>& motion);

  /// Fills `pairs` (rows by emitter, partners ascending). Team code (core/omp_team.hpp):
  /// on the caller's team inside one, else on a region of its own when `parallel`.
  /// With `periodic`, pairs are also found through the periodic boundaries, each with its
  /// partner's nearest image (grid and all-pairs).
  void find(const BoxArrays<Real>& boxes, Method method, bool parallel, PairList& pairs,
            const PeriodicView* periodic = nullptr);

  Real cell_size() const { return cell_size_; }
  std::size_t large_count() const { return large_.size(); }

 private:
  struct SmallExtent {
    double min_x = 0, min_y = 0, max_x = 0, max_y = 0, widest = 0;
  };
  /// Team code: every thread's share of the small particles' extent folded into
  /// extent_sum_; then take_small_extent, on one thread, reads it and starts the next sum.
  void fold_small_extent(const BoxArrays<Real>& boxes);
  SmallExtent take_small_extent();
  void bin(const BoxArrays<Real>& boxes);
  template <class Overlaps, class ScanCells, class Visit>
  void visit_with(std::int32_t i, Method method, Overlaps&& overlaps, ScanCells&& scan_cells,
                  Visit&& visit) const;
  template <class Visit>
  void visit_candidates(std::int32_t i, const BoxArrays<Real>& boxes, Method method,
                        Visit&& visit) const;
  // The periodic grid (broadphase/periodic_grid.hpp): cells that tile each periodic
  // direction, the other direction binned as in bin().
  void bin_periodic(const BoxArrays<Real>& boxes, const PeriodicView& p);
  template <class Visit>
  void visit_periodic(std::int32_t i, const BoxArrays<Real>& boxes, const PeriodicView& p,
                      Method method, Visit&& visit) const;
  void sort_into_cells(std::int64_t cells);

  std::size_t n_;
  Real cell_size_;
  std::vector<std::uint8_t> small_, free_;
  std::vector<std::int32_t> large_;
  // The grid of the current step: particles sorted by cell.
  Real origin_x_ = 0, origin_y_ = 0, grid_cell_ = 0;
  std::int64_t nx_ = 0, ny_ = 0;
  PeriodicGrid periodic_grid_;  ///< the periodic grid of the current step
  std::vector<std::int64_t> cell_of_;
  /// Sized for 4 cells a particle; bin() writes the cells a scene uses before reading them.
  UnfilledVector<std::int64_t> cell_start_, cell_count_;
  std::vector<std::int32_t> sorted_;
  std::vector<std::int64_t> row_count_;
  // The small particles' corners' extent and widest box, summed by the team's threads
  // (fold_small_extent); the empty sum between steps.
  SmallExtent extent_sum_ = empty_extent();
  static SmallExtent empty_extent() {
    const double big = std::numeric_limits<double>::max();
    return {big, big, std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest(),
            0};
  }
};

}  // namespace tridem
