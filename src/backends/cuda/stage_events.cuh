#pragma once
// The CUDA clock of run_step (core/stage_pipeline.hpp): an event recorded on the solver's
// stream before each step and after each of its stages, so that a stage's time is the GPU
// time between two events (its kernels, and any wait of the stream on the host in it).
// Recording costs a few microseconds of host time per event and never synchronises. The
// times are read only when a ring of kRingSteps steps is full and when a report asks: by
// then the events are complete (every step ends with the solver's own synchronisation),
// so reading them does not wait either.
#include "tridem/solver.hpp"

#include <cuda_runtime.h>

#include <array>
#include <cstdint>

namespace tridem::cuda {

class StageEvents {
 public:
  bool on = true;

  static constexpr int kRingSteps = 64;

  explicit StageEvents(cudaStream_t stream);
  ~StageEvents();
  StageEvents(const StageEvents&) = delete;
  StageEvents& operator=(const StageEvents&) = delete;

  void begin_step();
  void end_stage(Stage stage);
  void end_step();
  /// The totals over the completed steps (reads the ring).
  StageTimes times() const;

 private:
  void drain() const;

  cudaStream_t stream_;
  // Per step of the ring: an event before the step and one after each stage, and which
  // stage each interval was.
  std::array<std::array<cudaEvent_t, kStageCount + 1>, kRingSteps> events_{};
  std::array<std::array<Stage, kStageCount>, kRingSteps> stage_of_{};
  std::array<int, kRingSteps> stages_{};
  int slot_ = 0;     ///< the ring's slot of the step being recorded
  int stage_ = 0;    ///< stages recorded so far in this step
  mutable int drained_ = 0;  ///< slots already added to the totals
  mutable std::array<double, kStageCount> seconds_{};
  std::int64_t steps_ = 0;
};

}  // namespace tridem::cuda
