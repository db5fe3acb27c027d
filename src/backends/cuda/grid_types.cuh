#pragma once
// The data of the GPU cell grid, shared by the pair-list builder and its kernels.
#include "backends/cuda/device_views.cuh"

#include <cstdint>

namespace tridem::cuda {

/// Order-preserving map of a float or double to an unsigned integer, for atomicMin/Max.
template <class Real>
struct OrderedBits;

template <>
struct OrderedBits<float> {
  using Bits = unsigned int;
  __device__ static Bits encode(float v) {
    const Bits u = __float_as_uint(v);
    return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
  }
  __device__ static float decode(Bits u) {
    return __uint_as_float((u & 0x80000000u) ? (u & 0x7fffffffu) : ~u);
  }
};

template <>
struct OrderedBits<double> {
  using Bits = unsigned long long;
  __device__ static Bits encode(double v) {
    const Bits u = static_cast<Bits>(__double_as_longlong(v));
    return (u & 0x8000000000000000ull) ? ~u : (u | 0x8000000000000000ull);
  }
  __device__ static double decode(Bits u) {
    return __longlong_as_double(static_cast<long long>(
        (u & 0x8000000000000000ull) ? (u & 0x7fffffffffffffffull) : ~u));
  }
};

/// Extent of the build-box corners of the small particles and their widest build box, as
/// ordered bits.
template <class Real>
struct CornerBounds {
  typename OrderedBits<Real>::Bits min_x, min_y, max_x, max_y, widest;
};

/// The cell grid of one build.
template <class Real>
struct GridParams {
  Real origin_x, origin_y, cell;
  int nx, ny;
};

/// What the candidate search reads.
template <class Real>
struct CandidateSearch {
  int n;
  bool all_pairs;
  const std::uint8_t* free;
  const std::uint8_t* small;
  const Real *lo_x, *lo_y, *hi_x, *hi_y;  ///< build boxes
  const GridParams<Real>* grid;
  const unsigned int* cell_of;   ///< cell of each particle (unsorted)
  const int* sorted;             ///< particles by cell
  const int* cell_start;
  const int* cell_end;
  const int* large;              ///< particles too large for the grid (walls)
  int n_large;

  __device__ physics::Aabb<Real> box(int i) const {
    return physics::box_of(lo_x[i], lo_y[i], hi_x[i], hi_y[i]);
  }
};

}  // namespace tridem::cuda
