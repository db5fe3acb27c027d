#pragma once
// The decomposition method of the CUDA solver. The bookkeeping runs on the host, between
// steps, with the same Decomposition class as the CPU method: the paper also groups the
// particles and moves the borders on the CPU ("the control unit ... invoked between each
// time step"), and one implementation of it, tested against the cell grid, serves both
// backends. Each step the centroids and boxes come to the host (6 arrays), the owned and
// staged lists go back, and the GPU finds the pairs with one block per sub-domain
// (domain_kernels.cuh) into the PairListBuilder's rows; the other stages of the step are
// the grid's.
#include "backends/cuda/device_buffer.cuh"
#include "backends/cuda/domain_kernels.cuh"
#include "backends/cuda/pair_list_builder.cuh"
#include "broadphase/candidate_pairs.hpp"
#include "decomposition/decomposition.hpp"

#include <cstdint>
#include <vector>

namespace tridem::cuda {

template <class Real>
class DecomposedRows {
 public:
  /// Throws RunError when the capacity needs more shared memory than a block may have.
  DecomposedRows(const SimulationSettings& settings, const GridClasses& classes,
                 cudaStream_t stream);

  /// Brings the decomposition up to date from the GPU's state and builds the pair list.
  void build(const ParticleArrays<Real>& p, PairListBuilder<Real>& list);

  const Decomposition<Real>& decomposition() const { return decomposition_; }

 private:
  void upload_lists();

  Decomposition<Real> decomposition_;
  ContactFilter filter_;
  cudaStream_t stream_;
  std::size_t n_;
  std::size_t shared_bytes_;
  PinnedBuffer<Real> state_;  ///< centroids and boxes, 6 arrays of n
  DeviceBuffer<int> member_offset_, members_, owned_offset_, owned_, large_;
};

}  // namespace tridem::cuda
