#include "backends/cuda/decomposed_rows.cuh"

#include "tridem/error.hpp"

#include <fmt/format.h>
#include <type_traits>

namespace tridem::cuda {

namespace {

static_assert(std::is_same_v<std::int32_t, int>, "particle indices are uploaded as int");

}  // namespace

template <class Real>
DecomposedRows<Real>::DecomposedRows(const SimulationSettings& settings,
                                     const GridClasses& classes, cudaStream_t stream)
    : decomposition_(settings.decomposition, classes.cell, classes.small),
      assignment_(classes.small, stream),
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
  for (auto kernel : {domain_rows_kernel<Real, false>, domain_rows_kernel<Real, true>,
                      domain_rows_kernel<Real, false, true>, domain_rows_kernel<Real, true, true>})
    TRIDEM_CUDA_CHECK(cudaFuncSetAttribute(kernel, cudaFuncAttributeMaxDynamicSharedMemorySize,
                                           static_cast<int>(shared_bytes_)));
  centroids_.allocate(2 * n_);
  boxes_.allocate(4 * n_);
  large_.upload(decomposition_.large());
}

template <class Real>
void DecomposedRows<Real>::update_on_host(const ParticleArrays<Real>& p,
                                          const physics::PeriodicFrame* periodic) {
  const double* centroid[2] = {p.x, p.y};
  double* host_c[2];
  for (int a = 0; a < 2; ++a) {
    host_c[a] = centroids_.data() + static_cast<std::size_t>(a) * n_;
    if (n_ > 0)
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(host_c[a], centroid[a], n_ * sizeof(double),
                                        cudaMemcpyDeviceToHost, stream_));
  }
  const Real* box[4] = {p.lo_x, p.lo_y, p.hi_x, p.hi_y};
  Real* host[4];
  for (int a = 0; a < 4; ++a) {
    host[a] = boxes_.data() + static_cast<std::size_t>(a) * n_;
    if (n_ > 0)
      TRIDEM_CUDA_CHECK(cudaMemcpyAsync(host[a], box[a], n_ * sizeof(Real),
                                        cudaMemcpyDeviceToHost, stream_));
  }
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  // OpenMP on the host; the result does not depend on it.
  decomposition_.update({host_c[0], host_c[1], host[0], host[1], host[2], host[3]}, true, periodic);
  assignment_.take_from_host(decomposition_);
}

template <class Real>
void DecomposedRows<Real>::build(const ParticleArrays<Real>& p, PairListBuilder<Real>& list,
                                 const physics::PeriodicFrame* periodic) {
  // The first grouping on the host; afterwards the GPU, with the host's borders, unless a
  // sub-domain overflows them.
  if (builds_ == 0 || !assignment_.assign(p, decomposition_.capacity(), periodic))
    update_on_host(p, periodic);
  if (assignment_.largest_staged() > decomposition_.capacity())
    throw RunError("internal error: a sub-domain stages more particles than its capacity");
  assignment_.count_migrations();
  ++builds_;

  DomainLists lists{decomposition_.capacity(),
                    assignment_.member_offset(),
                    assignment_.members(),
                    assignment_.owned_offset(),
                    assignment_.owned(),
                    large_.data(),
                    static_cast<int>(decomposition_.large().size()),
                    filter_};
  if (periodic) {
    lists.frame = *periodic;
    fill_rows<true>(p, list, lists);
  } else {
    fill_rows<false>(p, list, lists);
  }
}

template <class Real>
template <bool kPeriodic>
void DecomposedRows<Real>::fill_rows(const ParticleArrays<Real>& p, PairListBuilder<Real>& list,
                                     const DomainLists& lists) {
  const int blocks = decomposition_.count();
  list.rebuild_with(
      [&](int* row_count) {
        // Particles that no sub-domain owns (walls) emit nothing: their rows stay empty.
        TRIDEM_CUDA_CHECK(cudaMemsetAsync(row_count, 0, n_ * sizeof(int), stream_));
        domain_rows_kernel<Real, false, kPeriodic>
            <<<blocks, kDomainThreads, shared_bytes_, stream_>>>(p, lists, row_count,
                                                                 RowHistory<Real>{});
        TRIDEM_CUDA_CHECK_LAUNCH("domain_rows_kernel (count)");
      },
      [&](const RowHistory<Real>& history) {
        domain_rows_kernel<Real, true, kPeriodic>
            <<<blocks, kDomainThreads, shared_bytes_, stream_>>>(p, lists, nullptr, history);
        TRIDEM_CUDA_CHECK_LAUNCH("domain_rows_kernel (fill)");
      });
}

template <class Real>
std::string DecomposedRows<Real>::summary() const {
  // Border moves and re-cut rows happen on the host; migrations and the staging of every
  // step are counted on the GPU.
  DecompositionStats s = decomposition_.stats();
  s.migrations = assignment_.migrations();
  s.max_members = assignment_.largest_staged();
  s.updates = builds_;
  return decomposition_summary(s, decomposition_.count(), decomposition_.rows(),
                               decomposition_.capacity());
}

template class DecomposedRows<float>;
template class DecomposedRows<double>;

}  // namespace tridem::cuda
