#pragma once
// A hook of the time loop for whoever watches a run as it happens (the live view of
// src/live/): called after every step, between steps, on the stepping thread.
#include <atomic>

namespace tridem {

class Solver;

class StepObserver {
 public:
  virtual ~StepObserver() = default;
  /// After each step. Must return at once when it has nothing to do (the run is not held
  /// up by its viewer); it may hold the run while the viewer paused it, but returns as
  /// soon as `interrupt` is set (the run's Ctrl-C).
  virtual void after_step(const Solver& solver, const std::atomic<int>* interrupt) = 0;
  /// Once, when the run has ended (finished, interrupted or blown up): the last state.
  virtual void run_ended(const Solver& solver) = 0;
};

}  // namespace tridem
