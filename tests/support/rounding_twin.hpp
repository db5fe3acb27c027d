#pragma once
// How far a run's own rounding carries it: a second serial run of the same scene whose
// velocity changes are perturbed each step by one rounding (unit roundoff `epsilon`,
// random sign from a fixed seed, so the twin is reproducible). Comparing a faster backend
// with the reference only makes sense up to what the reference itself keeps under rounding:
// in an unstable run (platen impacts, bonds softening and breaking: the loaded bonded disc
// of support/bonded_disc.hpp) one rounding of difference grows to 3e-9 m/s by step 100 and
// then about tenfold per 100 steps, to 8e-5 m/s by step 600 (RoundingTwin.*).
// The twin's spread, a running maximum, is that reproducible envelope.
//
// Kicks::VelocitiesAndPositions also rounds each position and angle that the step moved by
// one rounding of its value (epsilon·|x|): what the GPU's fused multiply-add does to
// x += v·dt, and what sets apart a shallow overlap computed from the difference of nearly
// equal coordinates. A pile whose contacts open and close (the servo box of
// support/program_scenes.hpp) parts from the reference from its first contacts that way,
// 150 times faster than the velocity kicks alone make it (H200, bench/results/
// gpu_checks_2026-12-02_nvidia-h200). Bodies of several triangles are kicked through their
// own pose and velocities, which place their members.
#include "support/gpu_compare.hpp"
#include "tridem/energy_budget.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"
#include "tridem/solver_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace tridem::test {

class RoundingTwin {
 public:
  enum class Kicks { Velocities, VelocitiesAndPositions };

  RoundingTwin(std::unique_ptr<Solver> twin, double epsilon, Kicks kicks = Kicks::Velocities,
               std::uint64_t seed = 12345)
      : twin_(std::move(twin)), epsilon_(epsilon), kicks_(kicks), state_(seed) {}

  /// Steps one at a time, rounding-kicking each step's velocity change (and positions).
  void advance(std::int64_t steps) {
    for (std::int64_t s = 0; s < steps; ++s) {
      twin_->save_state(before_);
      twin_->advance(1);
      // The step's forces, which load_state clears: shown by spread_from and snapshot().
      if (s + 1 == steps) {
        twin_->snapshot(snapshot_, true);
        energy_ = twin_->energy();
      }
      twin_->save_state(after_);
      kick_changes(after_.vx, before_.vx);
      kick_changes(after_.vy, before_.vy);
      kick_changes(after_.omega, before_.omega);
      kick_changes(after_.body_vx, before_.body_vx);
      kick_changes(after_.body_vy, before_.body_vy);
      kick_changes(after_.body_omega, before_.body_omega);
      if (kicks_ == Kicks::VelocitiesAndPositions) {
        kick_values(after_.x, before_.x);
        kick_values(after_.y, before_.y);
        kick_values(after_.theta, before_.theta);
        kick_values(after_.body_x, before_.body_x);
        kick_values(after_.body_y, before_.body_y);
        kick_values(after_.body_theta, before_.body_theta);
      }
      twin_->load_state(after_);
    }
  }

  /// The twin's largest difference from `reference` so far (reference at the twin's step),
  /// from its last step before that step's kicks.
  const Difference& spread_from(const Snapshot& reference) {
    const Difference d = max_difference(reference, snapshot_);
    spread_.position = std::max(spread_.position, d.position);
    spread_.angle = std::max(spread_.angle, d.angle);
    spread_.velocity = std::max(spread_.velocity, d.velocity);
    return spread_;
  }

  /// The twin's last step before its kicks, with that step's forces and contacts.
  const Snapshot& snapshot() const { return snapshot_; }
  /// The twin's energy budget at its last step, before its kicks (load_state clears the
  /// elastic energy of the contacts until the next step).
  const EnergyBudget& energy() const { return energy_; }
  /// The twin itself, for what else is compared (its bond state).
  Solver& solver() { return *twin_; }

 private:
  double kick() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return (state_ >> 63) != 0 ? epsilon_ : -epsilon_;
  }
  /// One rounding of each step's change.
  void kick_changes(std::vector<double>& after, const std::vector<double>& before) {
    for (std::size_t i = 0; i < after.size() && i < before.size(); ++i)
      after[i] += (after[i] - before[i]) * kick();
  }
  /// One rounding of each value the step changed (a wall at rest is left alone).
  void kick_values(std::vector<double>& after, const std::vector<double>& before) {
    for (std::size_t i = 0; i < after.size() && i < before.size(); ++i)
      if (after[i] != before[i]) after[i] += std::abs(after[i]) * kick();
  }

  std::unique_ptr<Solver> twin_;
  double epsilon_;
  Kicks kicks_;
  std::uint64_t state_;
  SolverState before_, after_;
  Snapshot snapshot_;
  EnergyBudget energy_;
  Difference spread_;
};

}  // namespace tridem::test
