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

namespace tridem {

/// Runs the stages of `pipeline` in order on `backend` (a member run_stage(Stage)), the
/// clock reading the time after each one. A stage that throws (a blow-up) ends the step
/// before the clock counts it.
template <class Backend, class Clock, std::size_t N>
void run_step(Backend& backend, const std::array<Stage, N>& pipeline, Clock& clock) {
  if (!clock.on) {
    for (const Stage stage : pipeline) backend.run_stage(stage);
    return;
  }
  clock.begin_step();
  for (const Stage stage : pipeline) {
    backend.run_stage(stage);
    clock.end_stage(stage);
  }
  clock.end_step();
}

/// The CPU's clock: steady_clock read once before the step and once after each stage.
class StageStopwatch {
 public:
  bool on = true;

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
    ++steps_;
  }
  StageTimes times() const {
    StageTimes t;
    for (int k = 0; k < kStageCount; ++k)
      t.seconds[k] = std::chrono::duration<double>(total_[k]).count();
    t.steps = steps_;
    t.clock = "steady_clock";
    return t;
  }
 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_{};
  std::array<Clock::duration, kStageCount> step_{}, total_{};
  std::int64_t steps_ = 0;
};

}  // namespace tridem
