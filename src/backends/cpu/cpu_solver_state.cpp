// CpuSolver's checkpoint side: the state a restart needs out of the solver and back in
// (contract in tridem/solver_state.hpp). The contact history lives in old_pairs_ and
// old_slip_ between steps (the buffers are swapped at the end of a step), which is where
// compute_pair_forces looks for it.
#include "backends/cpu/cpu_solver.hpp"

#include "core/history_rows.hpp"
#include "tridem/error.hpp"

namespace tridem {

template <class Real>
void CpuSolver<Real>::save_state(SolverState& out) const {
  out.step = step_;
  out.time = time_;
  // The checkpointed fields are double in every precision: copied exactly.
  SolverState::for_each_field([&](auto field) { out.column(field) = column(field); });
  // Bodies: their own pose and velocities (empty columns without bodies).
  SolverState::for_each_body_column([&](auto field) { out.column(field) = column(field); });
  append_history(out, n_, old_pairs_.offset.data(), old_pairs_.partner.data(), old_slip_.data());
  save_bonds(out, bonds_);
}

template <class Real>
void CpuSolver<Real>::load_state(const SolverState& in) {
  validate_solver_state(in, n_, n_bodies_, description());
  step_ = in.step;
  time_ = in.time;
  // The checkpointed fields are double in every precision: copied exactly; an empty Sum
  // reads as zeros. Forces are recomputed by the next step; until then nothing stale is
  // shown.
  SolverState::for_each_field([&](auto field) {
    for_each_array(column(field), [&](std::vector<double>& to, int k) {
      const std::vector<double>& from = array_at(in.column(field), k);
      if (from.empty()) to.assign(n_, 0.0);
      else to = from;
    });
  });
  for_each_particle_field([&](auto field) {
    if constexpr (decltype(field)::role == FieldRole::Force)
      for_each_array(column(field), [](auto& v, int) { std::fill(v.begin(), v.end(), Real(0)); });
  });
  // Bodies: validated to be as many as this solver's (none without bodies).
  SolverState::for_each_body_column([&](auto field) { column(field) = in.column(field); });
  for_each_body_field([&](auto field) {
    if constexpr (decltype(field)::role == FieldRole::Force)
      std::fill(column(field).begin(), column(field).end(), 0.0);
  });

  // Bonds: the damage and energy of the state; broken where every point is fully damaged.
  load_bonds(in, bonds_, description());

  history_rows(in, n_, old_pairs_.offset, old_pairs_.partner, old_slip_);
  list_kept_ = false;  // those rows are the history, not a list to keep
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
