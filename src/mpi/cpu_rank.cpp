#include "mpi/cpu_rank.hpp"

#include <cmath>

namespace tridem::mpi {

namespace {

/// Calls f(array) for each array of the State fields of a solver's storage, in the
/// order of particle_fields.hpp: what a ghost takes from its owner every step.
template <class Storage, class F>
void for_each_state_array(Storage& s, F&& f) {
  for_each_particle_field([&](auto field) {
    if constexpr (decltype(field)::role == FieldRole::State)
      for_each_array(s.column(field), [&](auto& v, int) { f(v); });
  });
}

/// Calls f(array) for each State array of a solver's bodies (body_x, ..., body_w).
template <class Storage, class F>
void for_each_body_state_array(Storage& s, F&& f) {
  for_each_body_field([&](auto field) {
    if constexpr (decltype(field)::role == FieldRole::State) f(s.column(field));
  });
}

}  // namespace

template <class Real>
void CpuRank<Real>::set_body_plan(const std::vector<std::int32_t>& send,
                                  const std::vector<std::int32_t>& receive) {
  body_send_ = send;
  body_receive_ = receive;
  body_send_buf_.assign(RankSolver<Real>::kBodyStateArrays * send.size(), 0.0);
  body_receive_buf_.assign(RankSolver<Real>::kBodyStateArrays * receive.size(), 0.0);
}

template <class Real>
void CpuRank<Real>::set_plan(const std::vector<std::int32_t>& send,
                             const std::vector<std::int32_t>& receive,
                             const std::vector<std::int32_t>& own) {
  send_ = send;
  receive_ = receive;
  own_ = own;
  const auto per = static_cast<std::size_t>(state_array_count());
  send_buf_.assign(per * send_.size(), 0.0);
  receive_buf_.assign(per * receive_.size(), 0.0);
  const auto& x = solver_.column(particle_field::x{});
  const auto& y = solver_.column(particle_field::y{});
  ref_x_.clear();
  ref_y_.clear();
  for (std::int32_t k : own_) {
    ref_x_.push_back(x[static_cast<std::size_t>(k)]);
    ref_y_.push_back(y[static_cast<std::size_t>(k)]);
  }
}

template <class Real>
bool CpuRank<Real>::take_ghosts_mid_step(const std::function<void()>& take,
                                         const std::function<void()>& poll) {
  // Elsewhere (a periodic cell, the paper's methods) the list is built every step from
  // every particle's box, ghosts included: nothing of the step can go before the exchange.
  if (!solver_.can_take_ghosts_mid_step()) return false;
  std::vector<std::uint8_t> received(solver_.size(), 0);
  for (std::int32_t i : receive_) received[static_cast<std::size_t>(i)] = 1;
  solver_.set_ghost_hooks(std::move(received), take, poll);
  return true;
}

template <class Real>
void CpuRank<Real>::pack() {
  std::size_t at = 0;
  for (std::int32_t i : send_)
    for_each_state_array(solver_, [&](const std::vector<double>& v) {
      send_buf_[at++] = v[static_cast<std::size_t>(i)];
    });
  at = 0;
  for (std::int32_t b : body_send_)
    for_each_body_state_array(solver_, [&](const std::vector<double>& v) {
      body_send_buf_[at++] = v[static_cast<std::size_t>(b)];
    });
}

template <class Real>
void CpuRank<Real>::unpack() {
  std::size_t at = 0;
  for (std::int32_t i : receive_)
    for_each_state_array(solver_, [&](std::vector<double>& v) {
      v[static_cast<std::size_t>(i)] = receive_buf_[at++];
    });
  at = 0;
  for (std::int32_t b : body_receive_)
    for_each_body_state_array(solver_, [&](std::vector<double>& v) {
      v[static_cast<std::size_t>(b)] = body_receive_buf_[at++];
    });
}

template <class Real>
bool CpuRank<Real>::drifted(double limit) const {
  const double limit2 = limit * limit;
  const auto& x = solver_.column(particle_field::x{});
  const auto& y = solver_.column(particle_field::y{});
  for (std::size_t q = 0; q < own_.size(); ++q) {
    const auto k = static_cast<std::size_t>(own_[q]);
    // Through a periodic boundary the move is the shortest one (a Lees-Edwards wrap also
    // slides x by the images' offset, which this leaves a drift: the plan is made anew).
    double dx = x[k] - ref_x_[q], dy = y[k] - ref_y_[q];
    if (cell_.x) dx = std::remainder(dx, cell_.x->length());
    if (cell_.y) dy = std::remainder(dy, cell_.y->length());
    // A non-finite state drifts too: the next plan's gather lets the check report it.
    if (!(dx * dx + dy * dy <= limit2)) return true;
  }
  return false;
}

template <class Real>
void CpuRank<Real>::energy_sums(std::vector<double>& out) const {
  const auto& energy = solver_.column(particle_field::energy{});
  const std::size_t n = solver_.size(), per = energy.size();
  out.assign(n * per, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < per; ++k) out[i * per + k] = energy[k][i];
}

namespace {

/// f(emitter, partner, force) for each slot of a pair list, rows in order.
template <class Real, class F>
void visit_pairs(const PairList& pl, const std::vector<physics::PairForce<Real>>& force, F&& f) {
  for (std::size_t e = 0; e + 1 < pl.offset.size(); ++e)
    for (std::int64_t s = pl.offset[e]; s < pl.offset[e + 1]; ++s)
      f(static_cast<std::int32_t>(e), pl.partner[static_cast<std::size_t>(s)],
        force[static_cast<std::size_t>(s)]);
}

}  // namespace

template <class Real>
void CpuRank<Real>::for_each_last_pair(const typename RankSolver<Real>::PairVisitor& f) const {
  if (solver_.step() == 0) return;
  visit_pairs(solver_.last_pairs(), solver_.last_forces(), f);
}

template <class Real>
void CpuRank<Real>::for_each_step_pair(const typename RankSolver<Real>::PairVisitor& f) const {
  visit_pairs(solver_.step_pairs(), solver_.last_forces(), f);
}

template <class Real>
void CpuRank<Real>::set_load(std::int32_t i, Vec2<Real> force, Real torque) {
  const auto k = static_cast<std::size_t>(i);
  solver_.column(particle_field::fx{})[k] = force.x;
  solver_.column(particle_field::fy{})[k] = force.y;
  solver_.column(particle_field::torque{})[k] = torque;
}

template <class Real>
void CpuRank<Real>::elastic_terms(
    const std::function<void(std::int32_t, std::int32_t, double)>& f) const {
  // CpuSolver::energy adds the pairs one by one.
  for_each_last_pair([&](std::int32_t e, std::int32_t j, const physics::PairForce<Real>& p) {
    f(e, j, static_cast<double>(p.elastic_energy));
  });
}

template class CpuRank<float>;
template class CpuRank<double>;

}  // namespace tridem::mpi
