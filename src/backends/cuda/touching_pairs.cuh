#pragma once
// The contact network of a frame, compacted on the GPU (issue 12): of the candidate pairs
// (some 7 per triangle in a dense pile) only the touching ones (about half) cross the bus,
// as rows of what a ContactRecord needs, in the list's slot order (rows by emitter,
// partners ascending: the order core/snapshot_fill.hpp's append_contacts gives on the
// host). Before, a frame copied every slot's load and detail and filtered them on the
// stepping thread: 0.54 s at 10^6 triangles on the H100.
#include "backends/cuda/cuda_check.cuh"
#include "backends/cuda/device_buffer.cuh"
#include "backends/cuda/device_views.cuh"
#include "core/snapshot_fill.hpp"
#include "physics/pair_record.hpp"

#include <cub/device/device_scan.cuh>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tridem::cuda {

using physics::TouchingPair;

template <class Real>
__global__ void count_touching_kernel(int n, PairArrays<Real> pairs, int* count) {
  const int e = blockIdx.x * blockDim.x + threadIdx.x;
  if (e > n) return;
  int c = 0;
  if (e < n)
    for (int s = pairs.offset[e]; s < pairs.offset[e + 1]; ++s) c += pairs.detail[s].touching;
  count[e] = c;  // count[n] = 0: the scan's last entry is the total
}

/// The touching pairs whose rows (numbered by `first`, the scan of the counts) lie in
/// [row_begin, row_end), into rows[0, row_end - row_begin). An emitter with no row there
/// returns after reading its two row numbers, before its slots: a pass costs its own rows
/// and 8 bytes a particle (at 10^8 triangles, ~143 passes of 0.8 GB for a frame).
template <class Real>
__global__ void fill_touching_kernel(int n, PairArrays<Real> pairs, const int* first, int row_begin,
                                     int row_end, TouchingPair<Real>* rows) {
  const int e = blockIdx.x * blockDim.x + threadIdx.x;
  if (e >= n) return;
  int at = first[e];
  if (at >= row_end || first[e + 1] <= row_begin) return;
  for (int s = pairs.offset[e]; s < pairs.offset[e + 1] && at < row_end; ++s)
    if (const physics::PairDetail<Real>& d = pairs.detail[s]; d.touching) {
      if (at >= row_begin)
        rows[at - row_begin] = {e,        pairs.partner[s], pairs.load[s].force_a, d.point,
                                d.normal, d.depth,          d.sliding ? 1 : 0};
      ++at;
    }
}

/// Queues on `stream` the download of the touching pairs of `pairs` (n particles), in
/// slot order, into `host`, and returns their number: the rows are there once the work
/// queued so far on `stream` is done. Waits for `stream` once, for the count. `host` is
/// page-locked (a copy from pageable memory runs at a fraction of the bus's speed); it
/// grows to the most contacts seen and is kept. The rows are compacted on the GPU and
/// downloaded `rows_per_copy` at a time through one scratch buffer (the stream's order
/// keeps a window's fill behind the last window's copy): a frame's GPU scratch is bounded
/// whatever the number of contacts (kContactRowsPerCopy, core/memory_estimate.hpp). The
/// scratch is taken from the stream's pool and given back after the download: frames are
/// rare against steps, and it would otherwise hold GPU memory for the whole run.
template <class Real>
std::size_t queue_touching_rows(int n, const PairArrays<Real>& pairs, cudaStream_t stream,
                                PinnedBuffer<TouchingPair<Real>>& host, std::size_t rows_per_copy) {
  constexpr int kBlock = 256;
  const int grid = (n + 1 + kBlock - 1) / kBlock;
  const StreamBuffer<int> first(static_cast<std::size_t>(n) + 1, stream);
  count_touching_kernel<Real><<<grid, kBlock, 0, stream>>>(n, pairs, first.data());
  TRIDEM_CUDA_CHECK_LAUNCH("count_touching_kernel");
  std::size_t bytes = 0;
  TRIDEM_CUDA_CHECK(
      cub::DeviceScan::ExclusiveSum(nullptr, bytes, first.data(), first.data(), n + 1, stream));
  {
    const StreamBuffer<unsigned char> temp(bytes, stream);
    TRIDEM_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(temp.data(), bytes, first.data(), first.data(),
                                                    n + 1, stream));
  }
  int total = 0;
  TRIDEM_CUDA_CHECK(
      cudaMemcpyAsync(&total, first.data() + n, sizeof total, cudaMemcpyDeviceToHost, stream));
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream));
  const auto count = static_cast<std::size_t>(total);
  if (host.size() < count) host.allocate(count + count / 8);
  if (count == 0) return 0;
  const std::size_t window = std::min(count, std::max<std::size_t>(rows_per_copy, 1));
  const StreamBuffer<TouchingPair<Real>> rows(window, stream);
  for (std::size_t begin = 0; begin < count; begin += window) {
    const std::size_t end = std::min(count, begin + window);
    fill_touching_kernel<Real><<<grid, kBlock, 0, stream>>>(
        n, pairs, first.data(), static_cast<int>(begin), static_cast<int>(end), rows.data());
    TRIDEM_CUDA_CHECK_LAUNCH("fill_touching_kernel");
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(host.data() + begin, rows.data(),
                                      (end - begin) * sizeof(TouchingPair<Real>),
                                      cudaMemcpyDeviceToHost, stream));
  }
  return count;
}

/// `count` downloaded touching pairs appended to `out.contacts` as contact records (cx, cy:
/// the snapshot's centroids), on the OpenMP threads.
template <class Real>
void append_touching_rows(Snapshot& out, const TouchingPair<Real>* rows, std::size_t count,
                          const double* cx, const double* cy) {
  const std::size_t before = out.contacts.size();
  out.contacts.resize(before + count);
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(static) if (n > 65536)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const TouchingPair<Real>& t = rows[k];
    physics::PairForce<Real> r;
    r.force_a = t.force;
    r.point = t.point;
    r.normal = t.normal;
    r.depth = t.depth;
    r.sliding = t.sliding != 0;
    r.touching = true;
    out.contacts[before + static_cast<std::size_t>(k)] = contact_record(
        static_cast<std::size_t>(t.emitter), static_cast<std::size_t>(t.partner), r, cx, cy);
  }
}

/// The touching pairs of `pairs` appended to `out.contacts` now (queue_touching_rows, a
/// wait for `stream`, append_touching_rows).
template <class Real>
void append_touching_contacts(Snapshot& out, int n, const PairArrays<Real>& pairs,
                              cudaStream_t stream, const double* cx, const double* cy,
                              PinnedBuffer<TouchingPair<Real>>& host, std::size_t rows_per_copy) {
  const std::size_t count = queue_touching_rows(n, pairs, stream, host, rows_per_copy);
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream));
  append_touching_rows(out, host.data(), count, cx, cy);
}

}  // namespace tridem::cuda
