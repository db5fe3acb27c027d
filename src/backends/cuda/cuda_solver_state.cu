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
  SolverState::for_each_field([&](auto field) {
    for_each_array(out.column(field), [&](std::vector<double>& to, int k) {
      to.resize(n_);  // download() copies as many values as the host vector holds
      array_at(d_.column(field), k).download(to);
    });
  });
  // Bodies: their own pose and velocities (empty columns without bodies).
  SolverState::for_each_body_column([&](auto field) {
    out.column(field).resize(n_bodies_);
    bodies_.column(field).download(out.column(field));
  });
  std::vector<int> offset, partner;
  std::vector<physics::PairSlip<Real>> slip;
  pairs_->download(offset, partner, &slip, nullptr);
  append_history(out, n_, offset.data(), partner.data(), slip.data());
  // Bonds: each point's damage and the energy released, as the CPU saves them.
  save_bonds(out, bonds_.download_state());
}

template <class Real>
void CudaSolver<Real>::load_state(const SolverState& in) {
  validate_solver_state(in, n_, n_bodies_, description());
  TRIDEM_CUDA_CHECK(cudaStreamSynchronize(stream_));
  // Bonds: validated and read as the CPU reads them (broken where every point is fully
  // damaged, no result until the next step), then uploaded.
  load_bonds(in, bonds_.host, description());
  bonds_.upload_state();
  // An empty Sum reads as zeros. Forces are recomputed by the next step; until then
  // nothing stale is shown.
  SolverState::for_each_field([&](auto field) {
    for_each_array(in.column(field), [&](const std::vector<double>& from, int k) {
      auto& to = array_at(d_.column(field), k);
      if (from.empty()) to.upload(std::vector<double>(n_, 0.0));
      else to.upload(from);
    });
  });
  for_each_particle_field([&](auto field) {
    using Field = decltype(field);
    if constexpr (Field::role == FieldRole::Force)
      for_each_array(d_.column(field), [&](auto& b, int) {
        b.upload(std::vector<typename Field::template type<Real>>(n_));
      });
  });
  // Bodies: validated to be as many as this solver's (none without bodies).
  if (n_bodies_ > 0) {
    SolverState::for_each_body_column(
        [&](auto field) { bodies_.column(field).upload(in.column(field)); });
    for_each_body_field([&](auto field) {
      if constexpr (decltype(field)::role == FieldRole::Force)
        bodies_.column(field).upload(std::vector<double>(n_bodies_, 0.0));
    });
  }
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
