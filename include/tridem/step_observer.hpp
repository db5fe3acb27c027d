#pragma once
// A hook of the time loop for whoever watches a run as it happens (the live view of
// src/live/): asked before each advance how many steps it may take, called after it,
// between steps, on the stepping thread.
#include <atomic>
#include <cstdint>

namespace tridem {

class Solver;

class StepObserver {
 public:
  virtual ~StepObserver() = default;
  /// Once, before the first step and inside the run's set-up (not its stepping time): what
  /// the observer must allocate or take from the solver before it can watch.
  virtual void run_starting(const Solver& /*solver*/) {}
  /// Before each advance of the loop: how many of the next `steps` (>= 1) may run before
  /// the next after_advance. `steps` when the observer has nothing to do sooner (the loop
  /// keeps its chunks, and the solver its fast multi-step path); fewer when it needs the
  /// state sooner (a frame falls due, a client is watching and may send a control), 1 to
  /// hold the run step by step (paused). `seconds_per_step`: the loop's last measured
  /// rate, 0 before the first chunk. Cheap: it is asked once per chunk.
  virtual std::int64_t steps_before_look(std::int64_t steps, double seconds_per_step) = 0;
  /// After each advance. Must return at once when it has nothing to do (the run is not
  /// held up by its viewer); it may hold the run while the viewer paused it, but returns
  /// as soon as `interrupt` is set (the run's Ctrl-C).
  virtual void after_advance(const Solver& solver, const std::atomic<int>* interrupt) = 0;
  /// Once, when the run has ended (finished, interrupted or blown up): the last state.
  virtual void run_ended(const Solver& solver) = 0;
};

}  // namespace tridem
