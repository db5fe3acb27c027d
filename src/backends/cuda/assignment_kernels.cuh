#pragma once
// The decomposition's per-step bookkeeping on the GPU, with the borders the host computed
// (decomposition/domain_map.hpp, the same code as the host's): each particle's owner from
// its centroid's cell, the hull of each sub-domain's owned boxes, and the overlap bands
// (every particle whose box reaches a hull, found from the particle's side with
// DomainMap::visit_near; in a periodic cell also through the particle's images:
// decomposition/periodic_images.hpp). Lists come out of CUB's stable radix sort keyed by
// sub-domain, so each holds its particles ascending, as the host's do. Integer atomics
// only count.
#include "backends/cuda/device_views.cuh"
#include "decomposition/band_visit.hpp"

#include <cfloat>
#include <cstdint>

namespace tridem::cuda {

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

/// The extent of the non-empty hulls, in double: one block.
template <class Real>
__global__ void extent_kernel(const Hull<Real>* hull, int domains, Hull<double>* extent) {
  constexpr int kThreads = 256;
  __shared__ double part[4][kThreads];
  Hull<double> e{DBL_MAX, DBL_MAX, -DBL_MAX, -DBL_MAX};
  for (int k = threadIdx.x; k < domains; k += kThreads) {
    const Hull<Real> h = hull[k];
    if (h.lo_x > h.hi_x) continue;  // owns nothing
    e = {fmin(e.lo_x, static_cast<double>(h.lo_x)), fmin(e.lo_y, static_cast<double>(h.lo_y)),
         fmax(e.hi_x, static_cast<double>(h.hi_x)), fmax(e.hi_y, static_cast<double>(h.hi_y))};
  }
  part[0][threadIdx.x] = e.lo_x;
  part[1][threadIdx.x] = e.lo_y;
  part[2][threadIdx.x] = e.hi_x;
  part[3][threadIdx.x] = e.hi_y;
  __syncthreads();
  for (int half = kThreads / 2; half > 0; half /= 2) {
    if (threadIdx.x < half)
      for (int a = 0; a < 4; ++a) {
        const double other = part[a][threadIdx.x + half];
        part[a][threadIdx.x] =
            a < 2 ? fmin(part[a][threadIdx.x], other) : fmax(part[a][threadIdx.x], other);
      }
    __syncthreads();
  }
  if (threadIdx.x == 0) *extent = {part[0][0], part[1][0], part[2][0], part[3][0]};
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
