#include "backends/cuda/decomposed_rows.cuh"

#include "tridem/error.hpp"

#include <fmt/format.h>
#include <type_traits>

namespace tridem::cuda {

namespace {

static_assert(std::is_same_v<std::int32_t, int>, "particle indices are uploaded as int");

/// Copies a host list into a device buffer grown to its high-water mark (with headroom).
void upload(DeviceBuffer<int>& buffer, const std::vector<std::int32_t>& host,
            cudaStream_t stream) {
  if (buffer.size() < host.size()) buffer.allocate(host.size() + host.size() / 5 + 16);
  if (!host.empty())
    TRIDEM_CUDA_CHECK(cudaMemcpyAsync(buffer.data(), host.data(), host.size() * sizeof(int),
                                      cudaMemcpyHostToDevice, stream));
}

}  // namespace

template <class Real>
DecomposedRows<Real>::DecomposedRows(const SimulationSettings& settings,
                                     const GridClasses& classes, cudaStream_t stream)
    : decomposition_(settings.decomposition, classes.cell, classes.small),
      filter_{settings.contact_test, settings.bbox_prefilter},
      stream_(stream),
      n_(classes.small.size()),
      shared_bytes_(StagedParticles<Real>::bytes(settings.decomposition.capacity)) {
  int device = 0, allowed = 0;
  TRIDEM_CUDA_CHECK(cudaGetDevice(&device));
  TRIDEM_CUDA_CHECK(
      cudaDeviceGetAttribute(&allowed, cudaDevAttrMaxSharedMemoryPerBlockOptin, device));
  if (shared_bytes_ > static_cast<std::size_t>(allowed))
    throw RunError(fmt::format(
        "[simulation.decomposition] capacity = {} needs {} KiB of shared memory per GPU block "
        "({} bytes a particle), more than the {} KiB this GPU allows: lower the capacity "
        "(the paper uses 256)",
        settings.decomposition.capacity, shared_bytes_ / 1024,
        StagedParticles<Real>::bytes(1), allowed / 1024));
  // Past the default 48 KiB a kernel must ask for its shared memory.
  for (auto kernel : {domain_rows_kernel<Real, false>, domain_rows_kernel<Real, true>})
    TRIDEM_CUDA_CHECK(cudaFuncSetAttribute(kernel, cudaFuncAttributeMaxDynamicSharedMemorySize,
                                           static_cast<int>(shared_bytes_)));
  state_.allocate(6 * n_);
  upload(large_, decomposition_.large(), stream_);
}

template <class Real>
void DecomposedRows<Real>::upload_lists() {
  const Decomposition<Real>& d = decomposition_;
  upload(member_offset_, d.member_offset(), stream_);
  upload(members_, d.member_list(), stream_);
  upload(owned_offset_, d.owned_offset(), stream_);
  upload(owned_, d.owned_list(), stream_);
}

template <class Real>
void DecomposedRows<Real>::build(const ParticleArrays<Real>& p, PairListBuilder<Real>& list) {
  // Centroids and boxes of this step to the host, then the bookkeeping there.
  const Real* from[6] = {p.x, p.y, p.lo_x, p.lo_y, p.hi_x, p.hi_y};
  Real* host[6];
  for (int a = 0; a < 6; ++a) {
    host[a] = state_.data() + static_cast<std::size_t>(a) * n_;
    if (n_ > 0)
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(host[a], from[a], n_ * sizeof(Real),
                                        cudaMemcpyDeviceToHost, stream_));
  }
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  decomposition_.update({host[0], host[1], host[2], host[3], host[4], host[5]});
  if (decomposition_.stats().max_members > decomposition_.capacity())
    throw RunError("internal error: a sub-domain stages more particles than its capacity");
  upload_lists();

  const DomainLists lists{decomposition_.capacity(), member_offset_.data(), members_.data(),
                          owned_offset_.data(),      owned_.data(),         large_.data(),
                          static_cast<int>(decomposition_.large().size()), filter_};
  const int blocks = decomposition_.count();
  list.rebuild_with(
      [&](int* row_count) {
        // Particles that no sub-domain owns (walls) emit nothing: their rows stay empty.
        TRIDEM_CUDA_CHECK(cudaMemsetAsync(row_count, 0, n_ * sizeof(int), stream_));
        domain_rows_kernel<Real, false><<<blocks, kDomainThreads, shared_bytes_, stream_>>>(
            p, lists, row_count, RowHistory<Real>{});
        TRIDEM_CUDA_CHECK_LAUNCH("domain_rows_kernel (count)");
      },
      [&](const RowHistory<Real>& history) {
        domain_rows_kernel<Real, true><<<blocks, kDomainThreads, shared_bytes_, stream_>>>(
            p, lists, nullptr, history);
        TRIDEM_CUDA_CHECK_LAUNCH("domain_rows_kernel (fill)");
      });
}

template class DecomposedRows<float>;
template class DecomposedRows<double>;

}  // namespace tridem::cuda
