#pragma once
// Whether the OpenMP solver's next step runs on its threads or on one, chosen by timing
// both. Each stage of a step is a parallel loop ending in a barrier; when other programs
// share the cores, a barrier waits for a thread the system has descheduled (a time slice,
// milliseconds), and a small step becomes many times slower than the serial one: the
// bundled example took 29 s serial and 22 minutes with OpenMP on two busy cores. Serial
// and OpenMP steps give the same bits (cpu_solver.hpp), so switching between them at any
// step changes only the time.
//
// The policy: run the chosen way (the threads, at first) for a gap, then the other way for
// a trial of at least kTrialSeconds (several scheduler time slices, so that a trial sees
// the stalls a busy machine causes), and switch when the trial's mean step is under
// kMargin times the gap's. Means are over whole gaps and trials, not a few steps: a few
// steps on busy cores are luck. The gap starts at kFirstGapSeconds, doubles while the
// choice holds, up to kLongestGapSeconds, and is never shorter than the last trial over
// kTrialShare, so that trials cost about 2% of the run whatever a step costs (a serial
// step of 10^6 triangles takes seconds).
#include "tridem/solver.hpp"

#include <algorithm>
#include <cstdint>

namespace tridem {

class ThreadChoice {
 public:
  static constexpr double kTrialSeconds = 0.05;
  static constexpr double kFirstGapSeconds = 0.1;
  static constexpr double kLongestGapSeconds = 10;
  static constexpr double kTrialShare = 0.02;
  static constexpr int kLeastSteps = 2;   ///< in a gap, and for the threads' first mean
  static constexpr double kMargin = 0.9;  ///< the other way must take under 90% of the time

  /// `threads`: the solver has threads to use (the openmp backend); `use`: the policy.
  ThreadChoice(bool threads, ThreadUse use) : threads_(threads), use_(use), chosen_(threads) {}

  /// Whether the coming step runs on the threads.
  bool parallel() const {
    if (!threads_ || use_ == ThreadUse::Always) return threads_;
    if (use_ == ThreadUse::Alternating) return steps_ % 2 == 0;
    return trying_ ? !chosen_ : chosen_;
  }

  /// Records the wall time of the step just run, the way parallel() said.
  void record(double seconds) {
    if (parallel()) ++parallel_steps_;
    ++steps_;
    if (!threads_ || use_ != ThreadUse::Measured) return;
    if (steps_ == 1) return;  // the first step pays for first touches of memory
    sum_ += seconds;
    ++count_;
    if (!trying_) {
      if (count_ < kLeastSteps || sum_ < std::max(gap_, last_trial_ / kTrialShare)) return;
      gap_mean_ = sum_ / count_;
      trying_ = true;
      sum_ = 0;
      count_ = 0;
      return;
    }
    if (sum_ < kTrialSeconds) return;
    const bool switch_over = sum_ / count_ < kMargin * gap_mean_;
    last_trial_ = sum_;
    trying_ = false;
    sum_ = 0;
    count_ = 0;
    if (switch_over) {
      chosen_ = !chosen_;
      ++switches_;
      gap_ = kFirstGapSeconds;
    } else {
      gap_ = std::min(2 * gap_, kLongestGapSeconds);
    }
  }

  std::int64_t steps() const { return steps_; }
  std::int64_t parallel_steps() const { return parallel_steps_; }
  std::int64_t switches() const { return switches_; }

 private:
  bool threads_;
  ThreadUse use_;
  bool chosen_;          ///< the way in use between trials
  bool trying_ = false;  ///< running the other way to time it
  std::int64_t steps_ = 0, parallel_steps_ = 0, switches_ = 0;
  double gap_ = kFirstGapSeconds;  ///< seconds of the chosen way before the next trial
  double last_trial_ = 0;          ///< seconds the last trial took
  double sum_ = 0, gap_mean_ = 0;  ///< seconds of the current gap or trial; the gap's mean step
  int count_ = 0;                  ///< its steps
};

}  // namespace tridem
