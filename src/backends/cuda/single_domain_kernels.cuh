#pragma once
// The paper's single-domain kernel (its §4) as the pair-list build of method
// "single-domain": one thread per particle in blocks of 64; the vertices and boxes of 64
// particles at a time are staged in shared memory, and each thread tests its particle
// against every one of them that it emits a pair with (broadphase/contact_filter.hpp: the
// CPU's rule and test), with the bounding-box pre-filter if asked. Each emitter writes its
// own row twice (count, then fill after a prefix sum), so no two threads write the same
// memory and the rows equal the CPU's (broadphase/single_domain.cpp).
#include "backends/cuda/device_views.cuh"
#include "backends/cuda/row_history.cuh"
#include "broadphase/contact_filter.hpp"

#include <cstdint>

namespace tridem::cuda {

/// The paper's block: 64 threads, one particle each, and a tile of 64 particles' geometry
/// in shared memory (the paper fits 4 such blocks, 256 particles, on one multiprocessor).
constexpr int kSingleDomainBlock = 64;

/// What the single-domain search reads: the current geometry, not grown by any skin.
template <class Real>
struct SingleDomainSearch {
  int n;
  const std::uint8_t* free;
  const std::uint8_t* small;
  TriangleArrays<Real> geometry;
  const int* large;  ///< ascending: particles too large for the grid (walls)
  int n_large;
  ContactFilter filter;
  physics::PeriodicFrame frame;  ///< the periodic cell (read by the kPeriodic kernels only)
};

/// One tile of particles in shared memory, structure of arrays: centroids (double) and
/// vertices about them, as the contact test's local frame reads them.
template <class Real>
struct SharedTile {
  double cx[kSingleDomainBlock], cy[kSingleDomainBlock];
  Real x[3][kSingleDomainBlock], y[3][kSingleDomainBlock];
  Real lo_x[kSingleDomainBlock], lo_y[kSingleDomainBlock];
  Real hi_x[kSingleDomainBlock], hi_y[kSingleDomainBlock];
  std::uint8_t small[kSingleDomainBlock], free[kSingleDomainBlock];

  __device__ void stage(const SingleDomainSearch<Real>& c, int k, int j) {
    const TriangleArrays<Real>& g = c.geometry;
    for (int v = 0; v < 3; ++v) {
      x[v][k] = g.x[v][j];
      y[v][k] = g.y[v][j];
    }
    cx[k] = g.cx[j];
    cy[k] = g.cy[j];
    lo_x[k] = g.lo_x[j];
    lo_y[k] = g.lo_y[j];
    hi_x[k] = g.hi_x[j];
    hi_y[k] = g.hi_y[j];
    small[k] = c.small[j];
    free[k] = c.free[j];
  }
  /// The tile read as the global arrays are, tile index for particle index.
  __device__ TriangleArrays<Real> view() const {
    return {{x[0], x[1], x[2]}, {y[0], y[1], y[2]}, lo_x, lo_y, hi_x, hi_y, cx, cy};
  }
};

/// Calls visit(j) for every pair (i, j) that this thread's particle i emits and that
/// passes the filter, partners ascending: the walls below the block first (few, read from
/// global memory), then every particle from the block's first on, tile by tile. Every
/// thread of the block must call it, also those past n: it synchronises the block.
/// kPeriodic: each partner is tested at its nearest image in c.frame
/// (passes_periodic_contact_test, the CPU's).
template <class Real, bool kPeriodic, class Visit>
__device__ inline void visit_contacts(const SingleDomainSearch<Real>& c, Visit&& visit) {
  __shared__ SharedTile<Real> tile;
  const int first = blockIdx.x * kSingleDomainBlock;
  const int i = first + static_cast<int>(threadIdx.x);
  const bool emitter = i < c.n && c.small[i] != 0;
  physics::Triangle<Real> a{};
  physics::Aabb<Real> box_a{};
  Vec2d origin{};  // the pair's frame: i's centroid, as pair_force takes it
  bool free_i = false;
  if (emitter) {
    origin = c.geometry.centroid(i);
    a = c.geometry.triangle(i, origin);
    box_a = c.geometry.box(i);
    free_i = c.free[i] != 0;
    for (int k = 0; k < c.n_large && c.large[k] < first; ++k) {
      const int j = c.large[k];
      if (!emits_pair(i, j, true, false, free_i, c.free[j] != 0)) continue;
      if constexpr (kPeriodic) {
        if (passes_periodic_contact_test(c.frame, origin, a, box_a, c.geometry, j, c.filter))
          visit(j);
      } else if (passes_contact_test(a, box_a, c.geometry.triangle(j, origin), c.geometry.box(j),
                                     c.filter)) {
        visit(j);
      }
    }
  }
  const TriangleArrays<Real> staged_geometry = tile.view();
  for (int base = first; base < c.n; base += kSingleDomainBlock) {
    const int staged = c.n - base < kSingleDomainBlock ? c.n - base : kSingleDomainBlock;
    if (static_cast<int>(threadIdx.x) < staged)
      tile.stage(c, static_cast<int>(threadIdx.x), base + static_cast<int>(threadIdx.x));
    __syncthreads();
    if (emitter)
      for (int k = 0; k < staged; ++k) {
        const int j = base + k;
        if (!emits_pair(i, j, true, tile.small[k] != 0, free_i, tile.free[k] != 0)) continue;
        if constexpr (kPeriodic) {
          if (passes_periodic_contact_test(c.frame, origin, a, box_a, staged_geometry, k, c.filter))
            visit(j);
        } else if (passes_contact_test(a, box_a, staged_geometry.triangle(k, origin),
                                       staged_geometry.box(k), c.filter)) {
          visit(j);
        }
      }
    __syncthreads();  // the tile is overwritten next
  }
}

template <class Real, bool kPeriodic = false>
__global__ void __launch_bounds__(kSingleDomainBlock)
    single_domain_count_kernel(SingleDomainSearch<Real> c, int* count) {
  int k = 0;
  visit_contacts<Real, kPeriodic>(c, [&k](int) { ++k; });
  const int i = blockIdx.x * kSingleDomainBlock + static_cast<int>(threadIdx.x);
  if (i < c.n) count[i] = k;
}

/// The rows, already ascending (visit_contacts' order), with their contact history.
template <class Real, bool kPeriodic = false>
__global__ void __launch_bounds__(kSingleDomainBlock)
    single_domain_fill_kernel(SingleDomainSearch<Real> c, RowHistory<Real> h) {
  const int i = blockIdx.x * kSingleDomainBlock + static_cast<int>(threadIdx.x);
  int at = i < c.n ? h.offset[i] : 0;
  visit_contacts<Real, kPeriodic>(c, [&](int j) { h.partner[at++] = j; });
  if (i < c.n) carry_history(i, h);
}

}  // namespace tridem::cuda
