#pragma once
// Kernels of the pair-list build, run when some particle has left its build box: the
// CPU's cell grid (broadphase/candidate_pairs.hpp) rebuilt on the GPU. Each small particle
// is binned by the lower-left corner of its build box (its box grown by the skin); cells
// are as wide as the widest build box, so a 3×3 scan finds every overlapping pair. The
// particles are sorted by cell with CUB's radix sort; each emitter then writes its own row
// twice (count, fill), so no two threads write the same memory and the result does not
// depend on scheduling.
#include "backends/cuda/grid_types.cuh"
#include "backends/cuda/row_history.cuh"
#include "backends/cuda/sorted_ranges.cuh"
#include "broadphase/emitter_rule.hpp"
#include "broadphase/grid_rules.hpp"
#include "broadphase/row_sort.hpp"

#include <cstdint>

namespace tridem::cuda {

template <class Real>
__global__ void init_bounds_kernel(CornerBounds<Real>* b) {
  using B = OrderedBits<Real>;
  b->min_x = b->min_y = ~typename B::Bits(0);
  b->max_x = b->max_y = b->widest = 0;
}

/// Build boxes from the current ones, and the extent of the small particles' corners.
template <class Real>
__global__ void grow_boxes_kernel(ParticleArrays<Real> p, const std::uint8_t* is_small,
                                  Real margin, CornerBounds<Real>* b) {
  using B = OrderedBits<Real>;
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  bool small = false;
  Real x = 0, y = 0, wide = 0;
  if (i < p.n) {
    x = p.lo_x[i] - margin;
    y = p.lo_y[i] - margin;
    const Real hx = p.hi_x[i] + margin, hy = p.hi_y[i] + margin;
    p.build_lo_x[i] = x;
    p.build_lo_y[i] = y;
    p.build_hi_x[i] = hx;
    p.build_hi_y[i] = hy;
    small = is_small[i] != 0;
    wide = static_cast<Real>(box_width(x, y, hx, hy));
  }
  // Warp-level extent first, then one atomic per warp and bound.
  const unsigned mask = __ballot_sync(0xffffffffu, small);
  if (mask == 0) return;
  typename B::Bits lo_x = small ? B::encode(x) : ~typename B::Bits(0);
  typename B::Bits lo_y = small ? B::encode(y) : ~typename B::Bits(0);
  typename B::Bits hi_x = small ? B::encode(x) : 0;
  typename B::Bits hi_y = small ? B::encode(y) : 0;
  typename B::Bits widest = small ? B::encode(wide) : 0;
  for (int d = 16; d > 0; d /= 2) {
    const auto ow = __shfl_down_sync(0xffffffffu, widest, d);
    widest = ow > widest ? ow : widest;
    const auto ox = __shfl_down_sync(0xffffffffu, lo_x, d);
    const auto oy = __shfl_down_sync(0xffffffffu, lo_y, d);
    const auto px = __shfl_down_sync(0xffffffffu, hi_x, d);
    const auto py = __shfl_down_sync(0xffffffffu, hi_y, d);
    lo_x = ox < lo_x ? ox : lo_x;
    lo_y = oy < lo_y ? oy : lo_y;
    hi_x = px > hi_x ? px : hi_x;
    hi_y = py > hi_y ? py : hi_y;
  }
  if ((threadIdx.x & 31) == 0) {
    atomicMin(&b->min_x, lo_x);
    atomicMin(&b->min_y, lo_y);
    atomicMax(&b->max_x, hi_x);
    atomicMax(&b->max_y, hi_y);
    atomicMax(&b->widest, widest);
  }
}

/// The grid over the corners, by the CPU's rule (fit_grid, cells no narrower than the widest
/// build box). Resets the bounds for the next build.
template <class Real>
__global__ void grid_kernel(CornerBounds<Real>* b, Real base_cell, long long max_cells,
                            GridParams<Real>* grid) {
  using B = OrderedBits<Real>;
  const Real min_x = B::decode(b->min_x), min_y = B::decode(b->min_y);
  const Real max_x = B::decode(b->max_x), max_y = B::decode(b->max_y);
  const GridFit fit = fit_grid(static_cast<double>(max_x) - static_cast<double>(min_x),
                               static_cast<double>(max_y) - static_cast<double>(min_y),
                               grid_cell_for(static_cast<double>(base_cell),
                                             static_cast<double>(B::decode(b->widest))),
                               static_cast<double>(max_cells));
  *grid = {min_x, min_y, static_cast<Real>(fit.cell), static_cast<int>(fit.nx),
           static_cast<int>(fit.ny)};
  b->min_x = b->min_y = ~typename B::Bits(0);
  b->max_x = b->max_y = b->widest = 0;
}

/// Cell of each particle (large ones get `beyond`, after every cell) and its index.
template <class Real>
__global__ void cell_key_kernel(CandidateSearch<Real> c, unsigned int beyond,
                                unsigned int* key, int* index) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= c.n) return;
  index[i] = i;
  if (!c.small[i]) {
    key[i] = beyond;
    return;
  }
  const GridParams<Real> g = *c.grid;
  key[i] = static_cast<unsigned int>(cell_coordinate(c.lo_x[i], g.origin_x, g.cell, std::int64_t{g.nx}) +
                                     cell_coordinate(c.lo_y[i], g.origin_y, g.cell, std::int64_t{g.ny}) * g.nx);
}

/// First and one-past-last sorted position of every occupied cell (others stay empty).
__global__ void cell_range_kernel(const unsigned int* sorted_key, int n, unsigned int beyond,
                                  int* cell_start, int* cell_end) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= n) return;
  const unsigned int key = sorted_key[k];
  if (key == beyond) return;
  if (k == 0 || sorted_key[k - 1] != key) cell_start[key] = k;
  if (k == n - 1 || sorted_key[k + 1] != key) cell_end[key] = k + 1;
}

/// Calls visit(j) for every pair (i, j) that i emits (broadphase/emitter_rule.hpp; all-pairs
/// has no size classes) with overlapping build boxes: the same visits as CandidatePairs on
/// the CPU.
template <class Real, class Visit>
__device__ inline void visit_candidates(const CandidateSearch<Real>& c, int i, Visit&& visit) {
  const bool free_i = c.free[i] != 0;
  const physics::Aabb<Real> box_i = c.box(i);
  auto consider = [&](int j, bool small_j) {
    if (emits_pair(i, j, true, small_j, free_i, c.free[j] != 0) &&
        physics::boxes_overlap(box_i, c.box(j)))
      visit(j);
  };
  if (c.all_pairs) {
    for (int j = i + 1; j < c.n; ++j) consider(j, true);
    return;
  }
  if (!c.small[i]) return;  // a large particle emits nothing: the small ones reach it
  const int nx = c.grid->nx, ny = c.grid->ny;
  const int cx = static_cast<int>(c.cell_of[i] % static_cast<unsigned int>(nx));
  const int cy = static_cast<int>(c.cell_of[i] / static_cast<unsigned int>(nx));
  for (int y = cy > 0 ? cy - 1 : 0; y <= (cy + 1 < ny ? cy + 1 : ny - 1); ++y)
    for (int x = cx > 0 ? cx - 1 : 0; x <= (cx + 1 < nx ? cx + 1 : nx - 1); ++x) {
      const int cell = x + y * nx;
      for (int k = c.cell_start[cell]; k < c.cell_end[cell]; ++k) consider(c.sorted[k], true);
    }
  for (int k = 0; k < c.n_large; ++k) consider(c.large[k], false);
}

/// The partners of each emitter by the grid (or all-pairs): visit_candidates.
template <class Real>
struct GridFinder {
  CandidateSearch<Real> c;
  template <class Visit>
  __device__ void operator()(int i, Visit&& visit) const {
    visit_candidates(c, i, visit);
  }
};

/// The length of every emitter's row, by a finder (GridFinder, PeriodicFinder).
template <class Finder>
__global__ void count_rows_kernel(Finder find, int n, int* count) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  int k = 0;
  find(i, [&k](int) { ++k; });
  count[i] = k;
}

/// The rows of the new list, partners ascending, each pair with its contact history.
template <class Real, class Finder>
__global__ void fill_rows_kernel(Finder find, int n, RowHistory<Real> h) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const int begin = h.offset[i], end = h.offset[i + 1];
  int at = begin;
  find(i, [&](int j) { h.partner[at++] = j; });
  insertion_sort(h.partner, begin, end);
  carry_history(i, h);
}

}  // namespace tridem::cuda
