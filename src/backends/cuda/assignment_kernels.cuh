#pragma once
// The decomposition's per-step bookkeeping on the GPU, with the borders the host computed
// (decomposition/domain_map.hpp, the same code as the host's): each particle's owner from
// its centroid's cell, the hull of each sub-domain's owned boxes, and the overlap bands
// (every particle whose box reaches a hull, found from the particle's side with
// DomainMap::visit_near). Lists come out of CUB's stable radix sort keyed by sub-domain, so
// each holds its particles ascending, as the host's do. Integer atomics only count.
#include "backends/cuda/device_views.cuh"
#include "decomposition/domain_map.hpp"

#include <cfloat>
#include <cstdint>

namespace tridem::cuda {

/// What the bookkeeping kernels read.
template <class Real>
struct AssignmentView {
  int n;
  int domains;
  DomainMap map;  ///< device pointers
  const std::uint8_t* small;
  const double *x, *y;  ///< centroids: double in every precision
  const Real *lo_x, *lo_y, *hi_x, *hi_y;

  __device__ std::int64_t cell_row(int i) const {
    return decomposition_cell(y[i], map.origin_y, map.cell);
  }
  __device__ std::int64_t cell_column(int i) const {
    return decomposition_cell(x[i], map.origin_x, map.cell);
  }
};

template <class Real>
__device__ inline Real largest_real();
template <>
__device__ inline float largest_real<float>() { return FLT_MAX; }
template <>
__device__ inline double largest_real<double>() { return DBL_MAX; }

/// Owner of every small particle (key: its sub-domain; particles larger than L get the key
/// `domains`, after every sub-domain, and owner -1), and the particle index as sort value.
template <class Real>
__global__ void owner_kernel(AssignmentView<Real> v, int* owner, int* key, int* index) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= v.n) return;
  index[i] = i;
  if (!v.small[i]) {
    owner[i] = -1;
    key[i] = v.domains;
    return;
  }
  const int k = v.map.owner(v.cell_row(i), v.cell_column(i));
  owner[i] = k;
  key[i] = k;
}

/// Hull of each sub-domain's owned boxes (thread per sub-domain, its owned list in order).
template <class Real>
__global__ void hull_kernel(AssignmentView<Real> v, const int* owned_offset, const int* owned,
                            Hull<Real>* hull) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= v.domains) return;
  Hull<Real> h{largest_real<Real>(), largest_real<Real>(), -largest_real<Real>(),
               -largest_real<Real>()};
  for (int o = owned_offset[k]; o < owned_offset[k + 1]; ++o) {
    const int p = owned[o];
    h.lo_x = v.lo_x[p] < h.lo_x ? v.lo_x[p] : h.lo_x;
    h.lo_y = v.lo_y[p] < h.lo_y ? v.lo_y[p] : h.lo_y;
    h.hi_x = v.hi_x[p] > h.hi_x ? v.hi_x[p] : h.hi_x;
    h.hi_y = v.hi_y[p] > h.hi_y ? v.hi_y[p] : h.hi_y;
  }
  hull[k] = h;
}

/// Calls reached(k) for every sub-domain whose hull particle i's box reaches, ascending k.
template <class Real, class Reached>
__device__ inline void visit_bands(const AssignmentView<Real>& v, const Hull<Real>* hull, int i,
                                   Reached&& reached) {
  const Real lx = v.lo_x[i], ly = v.lo_y[i], hx = v.hi_x[i], hy = v.hi_y[i];
  v.map.visit_near(v.cell_row(i), v.cell_column(i), [&](int k) {
    if (box_reaches(lx, ly, hx, hy, hull[k])) reached(k);
  });
}

/// How many bands each particle joins (count[n] stays 0 for the scan), and how many
/// particles each sub-domain stages.
template <class Real>
__global__ void band_count_kernel(AssignmentView<Real> v, const Hull<Real>* hull, int* count,
                                  int* staged) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= v.n) return;
  int c = 0;
  if (v.small[i])
    visit_bands(v, hull, i, [&](int k) {
      ++c;
      atomicAdd(&staged[k], 1);
    });
  count[i] = c;
}

/// Each particle's memberships at its place: key the sub-domain, value the particle.
template <class Real>
__global__ void band_fill_kernel(AssignmentView<Real> v, const Hull<Real>* hull,
                                 const int* position, int* key, int* value) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= v.n || !v.small[i]) return;
  int at = position[i];
  visit_bands(v, hull, i, [&](int k) {
    key[at] = k;
    value[at] = i;
    ++at;
  });
}

/// The most particles one sub-domain stages.
__global__ void largest_staged_kernel(const int* staged, int domains, int* largest) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k < domains) atomicMax(largest, staged[k]);
}

/// Counts the particles whose owner changed since the last step, then remembers the owners.
__global__ void migration_kernel(int n, const int* owner, int* last_owner,
                                 unsigned long long* migrations) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  const bool moved = i < n && last_owner[i] >= 0 && owner[i] != last_owner[i];
  if (i < n) last_owner[i] = owner[i];
  const unsigned mask = __ballot_sync(0xffffffffu, moved);
  if ((threadIdx.x & 31) == 0 && mask != 0)
    atomicAdd(migrations, static_cast<unsigned long long>(__popc(mask)));
}

}  // namespace tridem::cuda
