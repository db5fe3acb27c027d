#pragma once
// One step as code: a backend lists the stages it runs, in order (its pipeline), and
// implements run_stage(Stage); run_step drives them and lets a clock take the time between
// consecutive stages. The clocks take one reading per stage boundary and add nothing else
// to the step (no synchronisation, no allocation): steady_clock on the CPU (about 20 ns a
// reading), GPU events on CUDA (backends/cuda/stage_events.cuh).
#include "tridem/solver.hpp"

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>

namespace tridem {

/// One step the clock samples (its sample_this_step() said so): each stage timed.
template <class Backend, class Clock, std::size_t N>
void run_timed_step(Backend& backend, const std::array<Stage, N>& pipeline, Clock& clock) {
  const auto start = std::chrono::steady_clock::now();
  clock.begin_step();
  for (const Stage stage : pipeline) {
    backend.run_stage(stage);
    clock.end_stage(stage);
  }
  clock.end_step();
  clock.add_step_wall(std::chrono::steady_clock::now() - start);
}

/// Runs the stages of `pipeline` in order on `backend` (a member run_stage(Stage)), the
/// clock reading the time after each one. A stage that throws (a blow-up) ends the step
/// before the clock counts it.
template <class Backend, class Clock, std::size_t N>
void run_step(Backend& backend, const std::array<Stage, N>& pipeline, Clock& clock) {
  if (!clock.on) {  // timing off counts no steps at all
    for (const Stage stage : pipeline) backend.run_stage(stage);
    return;
  }
  if (clock.sample_this_step()) return run_timed_step(backend, pipeline, clock);
  const auto start = std::chrono::steady_clock::now();
  for (const Stage stage : pipeline) backend.run_stage(stage);
  clock.count_untimed_step();
  clock.add_step_wall(std::chrono::steady_clock::now() - start);
}

/// What both clocks share: whether timing is on, and which steps are timed. A clock that
/// costs a visible part of a small step (CUDA's six event records, about 10 µs against a
/// 46 µs launch-bound step: bench/results/stage_timing_2026-12-01_nvidia-h200) times one
/// step in `every` and scales its per-step means to all completed steps.
class StageSampling {
 public:
  using WallClock = std::chrono::steady_clock;
  bool on = true;
  int every = 1;
  /// Report the sampled steps' shares of the completed steps' wall time, rather than the
  /// samples' times scaled by the step count. A sampling clock that slows the steps it
  /// samples (CUDA's event records on a launch-bound step: the stages summed to 1.12-1.18
  /// times the wall time of 20 small steps on the H200) then still sums to the time the
  /// steps took; the split between stages is the samples'.
  bool shares_of_wall = false;

  /// The middle step of each window of `every`, not its first: the first step of a
  /// solver carries one-off costs (the first pair-list build, the kernels' first
  /// launches) that, scaled to every step, made the stages sum to several times the
  /// run's wall time (4.2 ms against 1.1 ms over 20 steps on the H200).
  bool sample_this_step() { return seen_++ % every == every / 2; }
  void count_untimed_step() { ++steps_; }
  /// The wall time of a completed step, timed or not (two clock readings a step).
  void add_step_wall(WallClock::duration d) { wall_ += d; }

 protected:
  /// Totals over the timed steps scaled to every completed step: by the step count, or
  /// (shares_of_wall) to the completed steps' wall time.
  void fill(StageTimes& t, const double* timed_seconds) const {
    t.steps = steps_;
    t.timed_steps = timed_;
    double scale = timed_ > 0 ? static_cast<double>(steps_) / static_cast<double>(timed_) : 0;
    if (shares_of_wall) {
      double timed_total = 0;
      for (int k = 0; k < kStageCount; ++k) timed_total += timed_seconds[k];
      scale = timed_total > 0 ? std::chrono::duration<double>(wall_).count() / timed_total : 0;
    }
    for (int k = 0; k < kStageCount; ++k) t.seconds[k] = timed_seconds[k] * scale;
  }
  void count_timed_step() {
    ++steps_;
    ++timed_;
  }

 private:
  std::int64_t seen_ = 0;  ///< steps asked about, timed or not
  std::int64_t steps_ = 0, timed_ = 0;
  WallClock::duration wall_{};  ///< of the completed steps
};

/// The CPU's clock: steady_clock read once before the step and once after each stage
/// (about 20 ns a reading: every step is timed).
class StageStopwatch : public StageSampling {
 public:
  /// A step stopped by a blow-up left its times in step_: they are dropped here.
  void begin_step() {
    step_.fill(Clock::duration::zero());
    last_ = Clock::now();
  }
  void end_stage(Stage stage) {
    const Clock::time_point now = Clock::now();
    step_[static_cast<int>(stage)] += now - last_;
    last_ = now;
  }
  /// Only completed steps reach the totals.
  void end_step() {
    for (int k = 0; k < kStageCount; ++k) total_[k] += step_[k];
    count_timed_step();
  }
  StageTimes times() const {
    double seconds[kStageCount];
    for (int k = 0; k < kStageCount; ++k)
      seconds[k] = std::chrono::duration<double>(total_[k]).count();
    StageTimes t;
    fill(t, seconds);
    t.clock = "steady_clock";
    return t;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_{};
  std::array<Clock::duration, kStageCount> step_{}, total_{};
};

}  // namespace tridem
