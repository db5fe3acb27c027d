// CpuSolver's checkpoint side: the state a restart needs out of the solver and back in
// (contract in tridem/solver_state.hpp). The contact history lives in old_pairs_ and
// old_slip_ between steps (the buffers are swapped at the end of a step), which is where
// compute_pair_forces looks for it.
#include "backends/cpu/cpu_solver.hpp"

#include <cmath>
#include <cstring>

namespace tridem {

static_assert(kSlipsPerPair == physics::kEdgeContacts);

namespace {

/// +0.0 is the slip of a pair without history; anything else, -0.0 included, must be kept
/// for the restarted run to be bit-identical.
template <class Real>
bool has_history(const physics::PairSlip<Real>& slip) {
  for (Real s : slip.s)
    if (s != Real(0) || std::signbit(s)) return true;
  return false;
}

}  // namespace

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
  out.pair_emitter.clear();
  out.pair_partner.clear();
  out.pair_slip.clear();
  // Rows are by emitter with partners ascending: already the order the contract asks for.
  for (std::size_t e = 0; e < n_; ++e)
    for (std::int64_t s = old_pairs_.offset[e]; s < old_pairs_.offset[e + 1]; ++s) {
      if (!has_history(old_slip_[s])) continue;
      std::array<double, kSlipsPerPair> slip{};
      for (int k = 0; k < kSlipsPerPair; ++k) slip[k] = old_slip_[s].s[k];
      out.pair_emitter.push_back(static_cast<std::int32_t>(e));
      out.pair_partner.push_back(old_pairs_.partner[s]);
      out.pair_slip.push_back(slip);
    }
}

template <class Real>
void CpuSolver<Real>::load_state(const SolverState& in) {
  validate_solver_state(in, n_, description());
  step_ = in.step;
  time_ = in.time;
  for (std::size_t i = 0; i < n_; ++i) {
    x_[i] = static_cast<Real>(in.x[i]);
    y_[i] = static_cast<Real>(in.y[i]);
    theta_[i] = static_cast<Real>(in.theta[i]);
    vx_[i] = static_cast<Real>(in.vx[i]);
    vy_[i] = static_cast<Real>(in.vy[i]);
    w_[i] = static_cast<Real>(in.omega[i]);
  }
  // Forces are recomputed by the next step; until then nothing stale is shown.
  std::fill(fx_.begin(), fx_.end(), Real(0));
  std::fill(fy_.begin(), fy_.end(), Real(0));
  std::fill(torque_.begin(), torque_.end(), Real(0));

  const auto m = static_cast<std::int64_t>(in.pairs());
  std::fill(old_pairs_.offset.begin(), old_pairs_.offset.end(), 0);
  for (std::int32_t e : in.pair_emitter) ++old_pairs_.offset[e + 1];
  for (std::size_t i = 0; i < n_; ++i) old_pairs_.offset[i + 1] += old_pairs_.offset[i];
  grow_to(old_pairs_.partner, m);
  grow_to(old_slip_, m);
  grow_to(result_, m);
  for (std::int64_t s = 0; s < m; ++s) {
    old_pairs_.partner[s] = in.pair_partner[s];
    for (int k = 0; k < kSlipsPerPair; ++k) old_slip_[s].s[k] = static_cast<Real>(in.pair_slip[s][k]);
    // The forces of those pairs are not stored: the loaded step reports no contacts.
    result_[s] = physics::PairForce<Real>{};
  }
}

// The class itself is instantiated in cpu_solver.cpp; these two members are defined here.
template void CpuSolver<float>::save_state(SolverState&) const;
template void CpuSolver<double>::save_state(SolverState&) const;
template void CpuSolver<float>::load_state(const SolverState&);
template void CpuSolver<double>::load_state(const SolverState&);

}  // namespace tridem
