// CudaSolver's checkpoint side (contract in tridem/solver_state.hpp). Between steps the
// contact history is the slips of the current pair list, rows by emitter as on the CPU;
// the GPU list may also hold pairs within the skin that do not touch, whose slips are
// +0.0 and are left out, so both backends save the same history for the same state.
#include "backends/cuda/cuda_solver.cuh"

#include "core/history_rows.hpp"

namespace tridem::cuda {

template <class Real>
void CudaSolver<Real>::save_state(SolverState& out) const {
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  out.step = step_;
  out.time = time_;
  std::vector<double>* fields[] = {&out.x, &out.y, &out.theta, &out.vx, &out.vy, &out.omega};
  const auto buffers = state_buffers();
  for (int k = 0; k < kStateArrays; ++k) {
    fields[k]->resize(n_);  // download() copies as many values as the host vector holds
    buffers[k]->download(*fields[k]);
  }
  std::vector<int> offset, partner;
  std::vector<physics::PairSlip<Real>> slip;
  pairs_->download(offset, partner, &slip, nullptr);
  append_history(out, n_, offset.data(), partner.data(), slip.data());
  for (int k = 0; k < kEnergyAccumulators; ++k) {
    out.energy[k].resize(n_);
    energy_[k].download(out.energy[k]);
  }
}

template <class Real>
void CudaSolver<Real>::load_state(const SolverState& in) {
  validate_solver_state(in, n_, description());
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  const std::vector<double>* fields[] = {&in.x, &in.y, &in.theta, &in.vx, &in.vy, &in.omega};
  DeviceBuffer<double>* buffers[] = {&x_, &y_, &theta_, &vx_, &vy_, &w_};
  for (int k = 0; k < kStateArrays; ++k) buffers[k]->upload(*fields[k]);
  // Forces are recomputed by the next step; until then nothing stale is shown.
  const std::vector<Real> zeros(n_, Real(0));
  for (auto* b : {&fx_, &fy_, &torque_}) b->upload(zeros);
  for (int k = 0; k < kEnergyAccumulators; ++k)
    energy_[k].upload(in.energy[k].empty() ? std::vector<double>(n_, 0.0) : in.energy[k]);
  step_ = in.step;
  time_ = in.time;
  std::vector<int> offset, partner;
  std::vector<physics::PairSlip<Real>> slip;
  history_rows(in, n_, offset, partner, slip);
  pairs_->load(offset, partner, slip);
  results_ = false;  // the loaded list has slips but no forces
  // New geometry and a forced rebuild, which carries the loaded slips into the new list.
  update_geometry();
}

template void CudaSolver<float>::save_state(SolverState&) const;
template void CudaSolver<double>::save_state(SolverState&) const;
template void CudaSolver<float>::load_state(const SolverState&);
template void CudaSolver<double>::load_state(const SolverState&);

}  // namespace tridem::cuda
