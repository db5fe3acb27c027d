#pragma once
// Where each key's run starts in a sorted array: the offsets of compressed rows made by a
// radix sort (the reverse index of the pair list, the decomposition's lists). A template,
// so that several translation units may launch it.
namespace tridem::cuda {

/// start[k] = first position of a key >= k in sorted[0, count), for k in [0, n].
template <class Key>
__global__ void range_start_kernel(const Key* sorted, int count, int n, int* start) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k > n) return;
  int lo = 0, hi = count;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (sorted[mid] < k) lo = mid + 1;
    else hi = mid;
  }
  start[k] = lo;
}

}  // namespace tridem::cuda
