#pragma once
// The decomposition's detection on the GPU (the paper's §5): one block per sub-domain. The
// block stages the sub-domain's particles (owned and overlap band, at most the capacity)
// in shared memory; each thread then takes owned emitters in turn and tests them against
// the staged particles of higher index and the walls, with the per-pair decision of the
// paper's methods (contact_filter.hpp). A block writes only the rows of the emitters its
// sub-domain owns, so no two blocks write the same memory. Run twice: count, then fill.
#include "backends/cuda/device_views.cuh"
#include "backends/cuda/row_history.cuh"
#include "broadphase/contact_filter.hpp"
#include "broadphase/row_sort.hpp"

#include <cstddef>
#include <cstdint>

namespace tridem::cuda {

/// The sub-domains of this step as the kernels read them (uploaded from the host).
struct DomainLists {
  int capacity;
  const int* member_offset;  ///< sub-domains + 1
  const int* members;        ///< staged particles of each sub-domain, ascending
  const int* owned_offset;   ///< sub-domains + 1
  const int* owned;          ///< owned particles of each sub-domain, ascending
  const int* large;          ///< particles larger than L: partners of every sub-domain
  int n_large;
  ContactFilter filter;
  physics::PeriodicFrame frame;  ///< the periodic cell at this step (kPeriodic kernels only)
};

constexpr int kDomainThreads = 128;

/// A block's shared memory: centroid (double), vertices about it, box, index and flag of
/// each staged particle.
template <class Real>
struct StagedParticles {
  double *cx, *cy;
  Real* x[3];
  Real* y[3];
  Real *lo_x, *lo_y, *hi_x, *hi_y;
  int* index;
  std::uint8_t* free;

  static std::size_t bytes(int capacity) {
    return static_cast<std::size_t>(capacity) *
           (2 * sizeof(double) + 10 * sizeof(Real) + sizeof(int) + 1);
  }
  /// Doubles first, then reals, then ints, then flags: each array aligned for its type.
  __device__ static StagedParticles carve(unsigned char* raw, int capacity) {
    StagedParticles s;
    s.cx = reinterpret_cast<double*>(raw);
    s.cy = s.cx + capacity;
    Real* r = reinterpret_cast<Real*>(s.cy + capacity);
    for (int k = 0; k < 3; ++k) {
      s.x[k] = r + k * capacity;
      s.y[k] = r + (3 + k) * capacity;
    }
    s.lo_x = r + 6 * capacity;
    s.lo_y = r + 7 * capacity;
    s.hi_x = r + 8 * capacity;
    s.hi_y = r + 9 * capacity;
    s.index = reinterpret_cast<int*>(r + 10 * capacity);
    s.free = reinterpret_cast<std::uint8_t*>(s.index + capacity);
    return s;
  }
  /// The staged particles read as the global arrays are, slot for particle index.
  __device__ TriangleArrays<Real> view() const {
    return {{x[0], x[1], x[2]}, {y[0], y[1], y[2]}, lo_x, lo_y, hi_x, hi_y, cx, cy};
  }
};

/// The current geometry of every particle.
template <class Real>
__device__ inline TriangleArrays<Real> geometry_of(const ParticleArrays<Real>& p) {
  return {{p.rel_x[0], p.rel_x[1], p.rel_x[2]},
          {p.rel_y[0], p.rel_y[1], p.rel_y[2]},
          p.lo_x, p.lo_y, p.hi_x, p.hi_y, p.x, p.y};
}

/// kFill = false: row_count[i] for every owned emitter i; true: its row, sorted, with its
/// contact history (carry_history). kPeriodic: each partner is tested at its nearest image
/// in d.frame (passes_periodic_contact_test, the CPU's); the bands hold those that can
/// touch an owned emitter through a boundary.
template <class Real, bool kFill, bool kPeriodic = false>
__global__ void __launch_bounds__(kDomainThreads)
    domain_rows_kernel(ParticleArrays<Real> p, DomainLists d, int* row_count, RowHistory<Real> t) {
  extern __shared__ __align__(16) unsigned char staged_raw[];
  const StagedParticles<Real> s = StagedParticles<Real>::carve(staged_raw, d.capacity);
  const TriangleArrays<Real> g = geometry_of(p), staged_g = s.view();
  const int k = blockIdx.x;
  const int first = d.member_offset[k];
  const int staged = d.member_offset[k + 1] - first;
  for (int m = threadIdx.x; m < staged; m += blockDim.x) {
    const int j = d.members[first + m];
    s.index[m] = j;
    s.cx[m] = p.x[j];
    s.cy[m] = p.y[j];
    for (int v = 0; v < 3; ++v) {
      s.x[v][m] = p.rel_x[v][j];
      s.y[v][m] = p.rel_y[v][j];
    }
    s.lo_x[m] = p.lo_x[j];
    s.lo_y[m] = p.lo_y[j];
    s.hi_x[m] = p.hi_x[j];
    s.hi_y[m] = p.hi_y[j];
    s.free[m] = p.free[j];
  }
  __syncthreads();
  for (int o = d.owned_offset[k] + threadIdx.x; o < d.owned_offset[k + 1]; o += blockDim.x) {
    const int i = d.owned[o];
    const Vec2d origin = g.centroid(i);  // the pair's frame, as pair_force takes it
    const physics::Triangle<Real> a = g.triangle(i, origin);
    const physics::Aabb<Real> box_a = g.box(i);
    const bool free_i = p.free[i] != 0;
    // Fill: the next free slot of i's row; count: how many partners so far.
    int at = 0;
    if constexpr (kFill) at = t.offset[i];
    // Partner j, slot `at` of geometry `from` (the staged copy or the global arrays).
    auto consider = [&](int j, const TriangleArrays<Real>& from, int at_from, bool small_j,
                        bool free_j) {
      if (!emits_pair(i, j, true, small_j, free_i, free_j)) return;
      if constexpr (kPeriodic) {
        if (!passes_periodic_contact_test(d.frame, origin, a, box_a, from, at_from, d.filter))
          return;
      } else if (!passes_contact_test(a, box_a, from.triangle(at_from, origin), from.box(at_from),
                                      d.filter)) {
        return;
      }
      if constexpr (kFill) t.partner[at] = j;
      ++at;
    };
    // Staged particles are ascending: i's partners among them are those after it.
    int lo = 0, hi = staged;
    while (lo < hi) {
      const int mid = (lo + hi) / 2;
      if (s.index[mid] <= i) lo = mid + 1;
      else hi = mid;
    }
    for (int m = lo; m < staged; ++m) consider(s.index[m], staged_g, m, true, s.free[m] != 0);
    for (int w = 0; w < d.n_large; ++w) {
      const int j = d.large[w];
      consider(j, g, j, false, p.free[j] != 0);
    }
    if constexpr (kFill) {
      insertion_sort(t.partner, t.offset[i], at);  // the walls come after the staged
      carry_history(i, t);
    }
    else row_count[i] = at;
  }
}

}  // namespace tridem::cuda
