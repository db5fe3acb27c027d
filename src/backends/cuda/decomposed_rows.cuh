#pragma once
// The decomposition method of the CUDA solver, as the paper splits it between CPU and GPU:
// the first grouping of the particles and every border move run on the host (the same
// Decomposition as the CPU method, tested against the cell grid), which hands the borders
// to the GPU; every step the GPU then finds owners and overlap bands itself
// (DomainAssignment) and the pairs with one block per sub-domain (domain_kernels.cuh), into
// the PairListBuilder's rows. Only when a sub-domain overflows does the state go to the
// host, whose update moves the borders and hands back borders and lists.
#include "backends/cuda/device_buffer.cuh"
#include "backends/cuda/domain_assignment.cuh"
#include "backends/cuda/domain_kernels.cuh"
#include "backends/cuda/pair_list_builder.cuh"
#include "broadphase/candidate_pairs.hpp"
#include "decomposition/decomposition.hpp"

#include <cstdint>
#include <string>

namespace tridem::cuda {

template <class Real>
class DecomposedRows {
 public:
  /// Throws RunError when the capacity needs more shared memory than a block may have.
  DecomposedRows(const SimulationSettings& settings, const GridClasses& classes,
                 cudaStream_t stream);

  /// Brings owners, bands and (on the host, when needed) borders up to date for the
  /// current state, and builds the pair list; in a periodic cell (`periodic`, the frame of
  /// this step) with the pairs through its boundaries.
  void build(const ParticleArrays<Real>& p, PairListBuilder<Real>& list,
             const physics::PeriodicFrame* periodic = nullptr);

  /// The decomposition's line of the run summary.
  std::string summary() const;

 private:
  void update_on_host(const ParticleArrays<Real>& p, const physics::PeriodicFrame* periodic);
  template <bool kPeriodic>
  void fill_rows(const ParticleArrays<Real>& p, PairListBuilder<Real>& list,
                 const DomainLists& lists);

  Decomposition<Real> decomposition_;
  DomainAssignment<Real> assignment_;
  ContactFilter filter_;
  cudaStream_t stream_;
  std::size_t n_;
  std::size_t shared_bytes_;
  std::int64_t builds_ = 0;
  PinnedBuffer<double> centroids_;  ///< for the host, 2 arrays of n
  PinnedBuffer<Real> boxes_;        ///< for the host, 4 arrays of n
  DeviceBuffer<int> large_;
};

}  // namespace tridem::cuda
