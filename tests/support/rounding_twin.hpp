#pragma once
// How far a run's own rounding carries it: a second serial run of the same scene whose
// velocity changes are perturbed each step by one rounding (unit roundoff `epsilon`,
// random sign from a fixed seed, so the twin is reproducible). Comparing a faster backend
// with the reference only makes sense up to what the reference itself keeps under rounding:
// in an unstable run (platen impacts, bonds softening and breaking: the loaded bonded disc
// of support/bonded_disc.hpp) one rounding of difference grows to 3e-9 m/s by step 100 and
// then about tenfold per 100 steps, to 8e-5 m/s by step 600 (RoundingTwin.*).
// The twin's spread, a running maximum, is that reproducible envelope.
#include "support/gpu_compare.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"
#include "tridem/solver_state.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>

namespace tridem::test {

class RoundingTwin {
 public:
  RoundingTwin(std::unique_ptr<Solver> twin, double epsilon)
      : twin_(std::move(twin)), epsilon_(epsilon) {}

  /// Steps one at a time, rounding-kicking each step's velocity change.
  void advance(std::int64_t steps) {
    for (std::int64_t s = 0; s < steps; ++s) {
      twin_->save_state(before_);
      twin_->advance(1);
      twin_->save_state(after_);
      for (std::size_t i = 0; i < after_.size(); ++i) {
        after_.vx[i] += (after_.vx[i] - before_.vx[i]) * kick();
        after_.vy[i] += (after_.vy[i] - before_.vy[i]) * kick();
        after_.omega[i] += (after_.omega[i] - before_.omega[i]) * kick();
      }
      twin_->load_state(after_);
    }
  }

  /// The twin's largest difference from `reference` so far (reference at the twin's step).
  const Difference& spread_from(const Snapshot& reference) {
    twin_->snapshot(snapshot_, true);
    const Difference d = max_difference(reference, snapshot_);
    spread_.position = std::max(spread_.position, d.position);
    spread_.angle = std::max(spread_.angle, d.angle);
    spread_.velocity = std::max(spread_.velocity, d.velocity);
    return spread_;
  }

 private:
  double kick() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return (state_ >> 63) != 0 ? epsilon_ : -epsilon_;
  }

  std::unique_ptr<Solver> twin_;
  double epsilon_;
  std::uint64_t state_ = 12345;
  SolverState before_, after_;
  Snapshot snapshot_;
  Difference spread_;
};

}  // namespace tridem::test
