#pragma once
// A CPU rank's local solver (core/rank_solver.hpp): the serial CpuSolver, its ghosts'
// states copied between its columns and host buffers.
#include "backends/cpu/cpu_solver.hpp"
#include "core/rank_solver.hpp"

#include <memory>

namespace tridem::mpi {

template <class Real>
class CpuRank final : public RankSolver<Real> {
 public:
  CpuRank(const Scene& scene, const ParticleModel& model, const TimeStep& ts,
          const SolverConfig& config)
      : solver_(scene, model, ts, config, false), cell_(scene.simulation.periodic) {}

  Solver& solver() override { return solver_; }
  const Solver& solver() const override { return solver_; }
  void set_check_hook(std::function<void()> hook) override {
    solver_.set_check_hook(std::move(hook));
  }
  void set_plan(const std::vector<std::int32_t>& send, const std::vector<std::int32_t>& receive,
                const std::vector<std::int32_t>& own) override;
  double* send_buffer() override { return send_buf_.data(); }
  double* receive_buffer() override { return receive_buf_.data(); }
  void set_body_plan(const std::vector<std::int32_t>& send,
                     const std::vector<std::int32_t>& receive) override;
  double* body_send_buffer() override { return body_send_buf_.data(); }
  double* body_receive_buffer() override { return body_receive_buf_.data(); }
  void pack() override;
  void unpack() override;
  bool drifted(double limit) const override;
  void energy_sums(std::vector<double>& out) const override;
  void for_each_last_pair(const typename RankSolver<Real>::PairVisitor& f) const override;
  void for_each_step_pair(const typename RankSolver<Real>::PairVisitor& f) const override;
  void set_load(std::int32_t i, Vec2<Real> force, Real torque) override;
  void bond_terms(const std::function<void(std::size_t, double, double)>& f) const override {
    const HostBondColumns<Real>& c = solver_.bond_columns();
    for (std::size_t k = 0; k < c.size(); ++k)
      f(k, solver_.step() > 0 ? static_cast<double>(c.result[k].elastic) : 0.0, c.dissipated[k]);
  }
  void elastic_terms(
      const std::function<void(std::int32_t, std::int32_t, double)>& f) const override;
  std::string transport() const override { return "through host memory"; }
  bool take_ghosts_mid_step(const std::function<void()>& take,
                            const std::function<void()>& poll) override;
  GhostOverlapCounts overlap_counts() const override { return solver_.overlap_counts(); }

 private:
  CpuSolver<Real> solver_;
  PeriodicCell cell_;  ///< a wrap is not a drift: moves are taken through the boundary
  std::vector<std::int32_t> send_, receive_, own_;
  std::vector<double> send_buf_, receive_buf_;
  std::vector<std::int32_t> body_send_, body_receive_;
  std::vector<double> body_send_buf_, body_receive_buf_;
  std::vector<double> ref_x_, ref_y_;  ///< own particles' centroids at the plan (own_ order)
};

}  // namespace tridem::mpi
