// CpuSolver's checkpoint side: the state a restart needs out of the solver and back in
// (contract in tridem/solver_state.hpp). The contact history lives in old_pairs_ and
// old_slip_ between steps (the buffers are swapped at the end of a step), which is where
// compute_pair_forces looks for it.
#include "backends/cpu/cpu_solver.hpp"

#include "core/history_rows.hpp"

namespace tridem {

template <class Real>
void CpuSolver<Real>::save_state(SolverState& out) const {
  out.step = step_;
  out.time = time_;
  out.x.assign(x_.begin(), x_.end());
  out.y.assign(y_.begin(), y_.end());
  out.theta.assign(theta_.begin(), theta_.end());
  out.vx.assign(vx_.begin(), vx_.end());
  out.vy.assign(vy_.begin(), vy_.end());
  out.omega.assign(w_.begin(), w_.end());
  append_history(out, n_, old_pairs_.offset.data(), old_pairs_.partner.data(), old_slip_.data());
  out.energy = energy_;
}

template <class Real>
void CpuSolver<Real>::load_state(const SolverState& in) {
  validate_solver_state(in, n_, description());
  step_ = in.step;
  time_ = in.time;
  // The state is double in every precision: copied exactly.
  x_ = in.x;
  y_ = in.y;
  theta_ = in.theta;
  vx_ = in.vx;
  vy_ = in.vy;
  w_ = in.omega;
  for (int k = 0; k < kEnergyAccumulators; ++k) {
    if (in.energy[k].empty()) energy_[k].assign(n_, 0.0);
    else energy_[k] = in.energy[k];
  }
  // Forces are recomputed by the next step; until then nothing stale is shown.
  std::fill(fx_.begin(), fx_.end(), Real(0));
  std::fill(fy_.begin(), fy_.end(), Real(0));
  std::fill(torque_.begin(), torque_.end(), Real(0));

  history_rows(in, n_, old_pairs_.offset, old_pairs_.partner, old_slip_);
  // The forces of those pairs are not stored: the loaded step reports no contacts.
  grow_to(result_, static_cast<std::int64_t>(in.pairs()));
  std::fill(result_.begin(), result_.end(), physics::PairForce<Real>{});
}

// The class itself is instantiated in cpu_solver.cpp; these two members are defined here.
template void CpuSolver<float>::save_state(SolverState&) const;
template void CpuSolver<double>::save_state(SolverState&) const;
template void CpuSolver<float>::load_state(const SolverState&);
template void CpuSolver<double>::load_state(const SolverState&);

}  // namespace tridem
