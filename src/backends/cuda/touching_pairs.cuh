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

#include <cub/device/device_scan.cuh>

#include <cstddef>
#include <vector>

namespace tridem::cuda {

/// What a contact record takes from one touching pair, and nothing more (40 bytes in
/// float, 72 in double, against 60 and 112 of the pair's whole result): its two particles,
/// the force on the emitter, the point (relative to the emitter's centroid), the normal,
/// the depth and whether it slid.
template <class Real>
struct TouchingPair {
  int emitter;
  int partner;
  Vec2<Real> force;
  Vec2<Real> point;
  Vec2<Real> normal;
  Real depth;
  int sliding;
};

template <class Real>
__global__ void count_touching_kernel(int n, PairArrays<Real> pairs, int* count) {
  const int e = blockIdx.x * blockDim.x + threadIdx.x;
  if (e > n) return;
  int c = 0;
  if (e < n)
    for (int s = pairs.offset[e]; s < pairs.offset[e + 1]; ++s) c += pairs.detail[s].touching;
  count[e] = c;  // count[n] = 0: the scan's last entry is the total
}

template <class Real>
__global__ void fill_touching_kernel(int n, PairArrays<Real> pairs, const int* first,
                                     TouchingPair<Real>* rows) {
  const int e = blockIdx.x * blockDim.x + threadIdx.x;
  if (e >= n) return;
  int at = first[e];
  for (int s = pairs.offset[e]; s < pairs.offset[e + 1]; ++s)
    if (const physics::PairDetail<Real>& d = pairs.detail[s]; d.touching)
      rows[at++] = {e,        pairs.partner[s], pairs.load[s].force_a, d.point,
                    d.normal, d.depth,          d.sliding ? 1 : 0};
}

/// Queues on `stream` the download of the touching pairs of `pairs` (n particles), in
/// slot order, into `host`, and returns their number: the rows are there once the work
/// queued so far on `stream` is done. Waits for `stream` once, for the count. `host` is
/// page-locked (a copy from pageable memory runs at a fraction of the bus's speed); it
/// grows to the most contacts seen and is kept. The device scratch is taken from the
/// stream's pool and given back after the download: frames are rare against steps, and it
/// would otherwise hold GPU memory for the whole run.
template <class Real>
std::size_t queue_touching_rows(int n, const PairArrays<Real>& pairs, cudaStream_t stream,
                                PinnedBuffer<TouchingPair<Real>>& host) {
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
  if (count > 0) {
    const StreamBuffer<TouchingPair<Real>> rows(count, stream);
    fill_touching_kernel<Real><<<grid, kBlock, 0, stream>>>(n, pairs, first.data(), rows.data());
    TRIDEM_CUDA_CHECK_LAUNCH("fill_touching_kernel");
    TRIDEM_CUDA_CHECK(
        cudaMemcpyAsync(host.data(), rows.data(), rows.bytes(), cudaMemcpyDeviceToHost, stream));
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
                              PinnedBuffer<TouchingPair<Real>>& host) {
  const std::size_t count = queue_touching_rows(n, pairs, stream, host);
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream));
  append_touching_rows(out, host.data(), count, cx, cy);
}

}  // namespace tridem::cuda
