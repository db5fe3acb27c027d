// The CUDA solver's contact copy for frames (tridem/contact_copy.hpp): start() compacts the
// touching pairs on the solver's stream (touching_pairs.cuh; it waits for their count, a
// fraction of a millisecond of kernels) and queues their download into pinned memory of
// its own behind them, so that the next steps' kernels queue behind the download; finish()
// on the frame thread waits for it and builds the records as the snapshot would.
#include "backends/cuda/cuda_solver.cuh"

#include <stdexcept>

namespace tridem::cuda {

template <class Real>
class CudaContactCopy final : public ContactCopy {
 public:
  explicit CudaContactCopy(const CudaSolver<Real>& solver) : solver_(solver) {
    TRIDEM_CUDA_CHECK(cudaGetDevice(&device_));  // the solver's (set by its constructor)
    // Blocking: the frame thread sleeps while it waits, rather than spinning a core.
    TRIDEM_CUDA_CHECK(
        cudaEventCreateWithFlags(&landed_, cudaEventDisableTiming | cudaEventBlockingSync));
  }
  ~CudaContactCopy() override {
    if (in_flight_) cudaEventSynchronize(landed_);
    cudaEventDestroy(landed_);
  }
  CudaContactCopy(const CudaContactCopy&) = delete;
  CudaContactCopy& operator=(const CudaContactCopy&) = delete;

  void start() override {
    const CudaSolver<Real>& s = solver_;
    step_ = s.step_;
    count_ = 0;
    if (step_ > 0)  // as snapshot(): no step, no contacts
      count_ = queue_touching_rows(static_cast<int>(s.n_), s.pairs_->arrays(), s.stream_, rows_,
                                   s.contact_rows_per_copy_);
    periodic_ = s.periodic_;
    if (periodic_) frame_ = periodic_frame_of(s.cell_, static_cast<double>(step_) * s.params_.dt);
    TRIDEM_CUDA_CHECK(cudaEventRecord(landed_, s.stream_));
    in_flight_ = true;
  }

  void finish(Snapshot& out) override {
    if (!in_flight_ || out.step != step_)
      throw std::logic_error("ContactCopy::finish: not the snapshot of the step started");
    // Another thread: on the solver's GPU, so that it does not open a context on GPU 0.
    TRIDEM_CUDA_CHECK(cudaSetDevice(device_));
    TRIDEM_CUDA_CHECK(cudaEventSynchronize(landed_));
    in_flight_ = false;
    out.contact_precision = kPrecisionOf<Real>;
    append_touching_rows(out, rows_.data(), count_, out.x.data(), out.y.data());
    if (periodic_) set_image_shifts(out, frame_, out.x.data(), out.y.data());
  }

 private:
  const CudaSolver<Real>& solver_;  ///< read in start() only
  int device_ = 0;
  PinnedBuffer<TouchingPair<Real>> rows_;
  cudaEvent_t landed_ = nullptr;
  bool in_flight_ = false;
  // Of the copy in flight:
  std::int64_t step_ = 0;
  std::size_t count_ = 0;
  bool periodic_ = false;
  physics::PeriodicFrame frame_{};
};

template <class Real>
std::unique_ptr<ContactCopy> CudaSolver<Real>::make_contact_copy() const {
  return std::make_unique<CudaContactCopy<Real>>(*this);
}

template std::unique_ptr<ContactCopy> CudaSolver<float>::make_contact_copy() const;
template std::unique_ptr<ContactCopy> CudaSolver<double>::make_contact_copy() const;

}  // namespace tridem::cuda
