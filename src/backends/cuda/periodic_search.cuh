#pragma once
// The pair-list build in a periodic cell: the CPU's periodic grid (broadphase/
// periodic_grid.hpp: cells that tile each periodic direction, corners binned modulo the
// grid, Lees-Edwards rows scanned about the shifted corner, the box test against the
// partner's nearest image) on the build boxes, with the kernels of broad_phase_kernels.cuh
// around it (the sort by cell, the rows, the history). Launched only for periodic scenes.
#include "backends/cuda/broad_phase_kernels.cuh"
#include "broadphase/periodic_grid.hpp"

namespace tridem::cuda {

/// What the periodic search adds to CandidateSearch: the cell at the build, the
/// centroids the nearest image is taken by, the build's grid (written on the device), and
/// how far a Lees-Edwards image may slide before the list is rebuilt.
struct PeriodicSearch {
  physics::PeriodicFrame frame;
  const double* x;
  const double* y;
  const PeriodicGrid* grid;
  double sheared_slack;
};

/// The periodic grid over the build boxes' corners (fit_periodic_grid; cells no narrower
/// than the widest build box plus the sheared slack). Resets the bounds for the next build.
template <class Real>
__global__ void periodic_grid_kernel(CornerBounds<Real>* b, double base_cell, double slack,
                                     long long max_cells, physics::PeriodicFrame frame,
                                     PeriodicGrid* grid) {
  using B = OrderedBits<Real>;
  const double widest = static_cast<double>(B::decode(b->widest)) + slack;
  *grid = fit_periodic_grid(
      frame, static_cast<double>(B::decode(b->min_x)), static_cast<double>(B::decode(b->min_y)),
      static_cast<double>(B::decode(b->max_x)), static_cast<double>(B::decode(b->max_y)),
      grid_cell_for(base_cell + slack, widest), static_cast<double>(max_cells));
  b->min_x = b->min_y = ~typename B::Bits(0);
  b->max_x = b->max_y = b->widest = 0;
}

/// Cell of each particle in the periodic grid (large ones get `beyond`) and its index.
template <class Real>
__global__ void periodic_cell_key_kernel(CandidateSearch<Real> c, PeriodicSearch ps,
                                         unsigned int beyond, unsigned int* key, int* index) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= c.n) return;
  index[i] = i;
  key[i] = c.small[i]
               ? static_cast<unsigned int>(periodic_grid_cell(
                     *ps.grid, static_cast<double>(c.lo_x[i]), static_cast<double>(c.lo_y[i])))
               : beyond;
}

/// The partners of each emitter in a periodic cell: CandidatePairs::visit_periodic's visits
/// on the build boxes.
template <class Real>
struct PeriodicFinder {
  CandidateSearch<Real> c;
  PeriodicSearch ps;

  template <class Visit>
  __device__ void operator()(int i, Visit&& visit) const {
    const bool free_i = c.free[i] != 0;
    const physics::Aabb<Real> box_i = c.box(i);
    const Vec2d ci{ps.x[i], ps.y[i]};
    auto consider = [&](int j, bool small_j) {
      if (emits_pair(i, j, true, small_j, free_i, c.free[j] != 0) &&
          periodic_boxes_overlap(ps.frame, ci, Vec2d{ps.x[j], ps.y[j]}, box_i, c.box(j),
                                 ps.sheared_slack))
        visit(j);
    };
    if (c.all_pairs) {
      for (int j = i + 1; j < c.n; ++j) consider(j, true);
      return;
    }
    if (!c.small[i]) return;  // a large particle emits nothing: the small ones reach it
    const PeriodicGrid g = *ps.grid;
    for_each_periodic_neighbour_cell(
        g, static_cast<double>(c.lo_x[i]), static_cast<double>(c.lo_y[i]),
        static_cast<std::int64_t>(c.cell_of[i]), [&](std::int64_t cell) {
          for (int k = c.cell_start[cell]; k < c.cell_end[cell]; ++k) consider(c.sorted[k], true);
        });
    for (int k = 0; k < c.n_large; ++k) consider(c.large[k], false);
  }
};

}  // namespace tridem::cuda
