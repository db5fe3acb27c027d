// The live view's copy of the CUDA solver's state (tridem/state_copy.hpp), without holding
// the steps up for long. start(), on the stepping thread between steps, queues on the
// solver's stream what a snapshot and energy() would compute (the walls' forces, the rows'
// and bonds' elastic energy) and a device-to-device copy of the shown fields, the energy
// sums and the bonds' damage into a device staging buffer of its own (some 0.2 GB of memory
// traffic at 10^6 triangles in double: well under a millisecond of an H200's bandwidth),
// and the next step's kernels queue behind it. Then a
// stream of its own downloads the staging into pinned memory (an event after the staged
// copy orders it, an event after the download says it has landed), beside the next steps.
// finish(), on the live view's server thread, waits for that event and converts in the
// orders of snapshot() and energy(), so that the frame is the snapshot's and the budget
// energy()'s to the bit.
#include "backends/cuda/body_kernels.cuh"
#include "backends/cuda/bond_kernels.cuh"
#include "backends/cuda/cuda_solver.cuh"
#include "backends/cuda/step_kernels.cuh"
#include "core/bond_columns.hpp"
#include "core/state_copy_fields.hpp"

namespace tridem::cuda {

namespace {

constexpr int kCopyBlock = 256;

int copy_blocks(std::size_t items) {
  return static_cast<int>((items + kCopyBlock - 1) / kCopyBlock);
}

/// Each array of the staging starts 8-byte aligned.
template <class T>
std::size_t aligned_bytes(std::size_t n) {
  return (n * sizeof(T) + 7) / 8 * 8;
}

}  // namespace

template <class Real>
class CudaStateCopy final : public StateCopy {
 public:
  explicit CudaStateCopy(const CudaSolver<Real>& solver)
      : solver_(solver), n_(solver.n_), bonds_(solver.bonds_.size()) {
    std::size_t bytes = 0;
    Snapshot::for_each_field([&](auto field) {
      using Field = decltype(field);
      bytes += Field::count * aligned_bytes<typename Field::template type<Real>>(n_);
    });
    bytes += (1 + kEnergyAccumulators) * aligned_bytes<double>(n_);  // rows' elastic, sums
    bytes += aligned_bytes<Real>(bonds_ * physics::kBondPoints) + 2 * aligned_bytes<double>(bonds_);
    TRIDEM_CUDA_CHECK(cudaGetDevice(&device_));  // the solver's (set by its constructor)
    staging_.allocate(bytes);
    host_.allocate(bytes);
    TRIDEM_CUDA_CHECK(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking));
    TRIDEM_CUDA_CHECK(cudaEventCreateWithFlags(&staged_, cudaEventDisableTiming));
    // Blocking: the server's thread sleeps while it waits, rather than spinning a core.
    TRIDEM_CUDA_CHECK(
        cudaEventCreateWithFlags(&landed_, cudaEventDisableTiming | cudaEventBlockingSync));
  }

  ~CudaStateCopy() override {
    if (in_flight_) cudaEventSynchronize(landed_);
    cudaEventDestroy(landed_);
    cudaEventDestroy(staged_);
    cudaStreamDestroy(stream_);
  }
  CudaStateCopy(const CudaStateCopy&) = delete;
  CudaStateCopy& operator=(const CudaStateCopy&) = delete;

  void start() override {
    const CudaSolver<Real>& s = solver_;
    cudaStream_t solver_stream = s.stream_;
    step_ = s.step_;
    time_ = s.time_;
    elastic_ = s.results_;
    const ParticleArrays<Real> p = s.arrays();
    if (step_ > 0) {  // the walls' forces, summed only for output (as snapshot())
      gather_kernel<Real><<<copy_blocks(n_), kCopyBlock, 0, solver_stream>>>(
          p, s.pairs_->arrays(), s.params_, s.status_.data(), true, s.bond_arrays());
      TRIDEM_CUDA_CHECK_LAUNCH("gather_kernel");
      if (s.n_bodies_ > 0) {
        body_gather_kernel<Real><<<copy_blocks(s.n_bodies_), kCopyBlock, 0, solver_stream>>>(
            p, s.body_arrays(), s.params_, s.status_.data(), true);
        TRIDEM_CUDA_CHECK_LAUNCH("body_gather_kernel");
      }
    }
    if (elastic_) {  // the rows' and bonds' elastic energy of the last step (as energy())
      row_elastic_kernel<Real><<<copy_blocks(n_), kCopyBlock, 0, solver_stream>>>(
          static_cast<int>(n_), s.pairs_->arrays(), s.d_.row_elastic.data());
      TRIDEM_CUDA_CHECK_LAUNCH("row_elastic_kernel");
      if (bonds_ > 0) {
        bond_elastic_kernel<Real><<<copy_blocks(bonds_), kCopyBlock, 0, solver_stream>>>(
            s.bond_arrays(), s.bonds_.elastic.data());
        TRIDEM_CUDA_CHECK_LAUNCH("bond_elastic_kernel");
      }
    }
    std::size_t at = 0;
    auto stage = [&](const auto* from, std::size_t count) {
      using T = std::remove_cv_t<std::remove_pointer_t<decltype(from)>>;
      if (count > 0)
        TRIDEM_CUDA_CHECK(cudaMemcpyAsync(staging_.data() + at, from, count * sizeof(T),
                                          cudaMemcpyDeviceToDevice, solver_stream));
      at += aligned_bytes<T>(count);
    };
    Snapshot::for_each_field([&](auto field) {
      using T = typename decltype(field)::template type<Real>;
      for_each_array(s.d_.column(field),
                     [&](const DeviceBuffer<T>& from, int) { stage(from.data(), n_); });
    });
    stage(s.d_.row_elastic.data(), n_);
    for (int k = 0; k < kEnergyAccumulators; ++k) stage(s.d_.energy[k].data(), n_);
    stage(s.bonds_.d.damage.data(), bonds_ * physics::kBondPoints);
    stage(s.bonds_.elastic.data(), bonds_);
    stage(s.bonds_.d.dissipated.data(), bonds_);
    TRIDEM_CUDA_CHECK(cudaEventRecord(staged_, solver_stream));
    TRIDEM_CUDA_CHECK(cudaStreamWaitEvent(stream_, staged_, 0));
    TRIDEM_CUDA_CHECK(
        cudaMemcpyAsync(host_.data(), staging_.data(), at, cudaMemcpyDeviceToHost, stream_));
    TRIDEM_CUDA_CHECK(cudaEventRecord(landed_, stream_));
    in_flight_ = true;
  }

  EnergyBudget finish(Snapshot& out) override {
    // Another thread: on the solver's GPU, so that it does not open a context on GPU 0.
    TRIDEM_CUDA_CHECK(cudaSetDevice(device_));
    TRIDEM_CUDA_CHECK(cudaEventSynchronize(landed_));
    in_flight_ = false;
    out.step = step_;
    out.time = time_;
    resize_copied_fields(out, n_, bonds_);
    std::size_t at = 0;
    auto staged = [&](auto type, std::size_t count) {
      using T = decltype(type);
      const auto* values = reinterpret_cast<const T*>(host_.data() + at);
      at += aligned_bytes<T>(count);
      return values;
    };
    Snapshot::for_each_field([&](auto field) {
      using T = typename decltype(field)::template type<Real>;
      for_each_array(out.column(field), [&](std::vector<double>& to, int) {
        const T* from = staged(T{}, n_);
        for (std::size_t i = 0; i < n_; ++i) to[i] = static_cast<double>(from[i]);
      });
    });
    // energy()'s sums, in its order: each array in index order, the bonds ascending.
    double totals[kEnergyAccumulators + 1] = {};
    const double* row_elastic = staged(double{}, n_);
    if (elastic_)
      for (std::size_t i = 0; i < n_; ++i) totals[kEnergyAccumulators] += row_elastic[i];
    for (int k = 0; k < kEnergyAccumulators; ++k) {
      const double* sums = staged(double{}, n_);
      for (std::size_t i = 0; i < n_; ++i) totals[k] += sums[i];
    }
    const Real* damage = staged(Real{}, bonds_ * physics::kBondPoints);
    for (std::size_t b = 0; b < bonds_; ++b) out.bond_damage[b] = mean_bond_damage(damage, b);
    EnergyBudget budget;
    budget.elastic = totals[kEnergyAccumulators];
    const double* bond_elastic = staged(double{}, bonds_);
    const double* bond_dissipated = staged(double{}, bonds_);
    for (std::size_t b = 0; b < bonds_; ++b) {
      if (elastic_) budget.elastic += bond_elastic[b];
      budget.dissipated_fracture += bond_dissipated[b];
    }
    budget.dissipated_damping = totals[kDissipatedDamping];
    budget.dissipated_friction = totals[kDissipatedFriction];
    budget.dissipated_local = totals[kDissipatedLocal];
    budget.wall_work = totals[kWallWork];
    return budget;
  }

 private:
  const CudaSolver<Real>& solver_;  ///< read in start() only
  std::size_t n_, bonds_;
  int device_ = 0;
  DeviceBuffer<unsigned char> staging_;
  PinnedBuffer<unsigned char> host_;
  cudaStream_t stream_ = nullptr;
  cudaEvent_t staged_ = nullptr, landed_ = nullptr;
  bool in_flight_ = false;
  // Of the copy in flight:
  std::int64_t step_ = 0;
  double time_ = 0;
  bool elastic_ = false;  ///< the pair list held a step's results (energy()'s results_)
};

template <class Real>
std::unique_ptr<StateCopy> CudaSolver<Real>::make_state_copy() const {
  return std::make_unique<CudaStateCopy<Real>>(*this);
}

template std::unique_ptr<StateCopy> CudaSolver<float>::make_state_copy() const;
template std::unique_ptr<StateCopy> CudaSolver<double>::make_state_copy() const;

}  // namespace tridem::cuda
