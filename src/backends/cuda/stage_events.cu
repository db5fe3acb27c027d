#include "backends/cuda/stage_events.cuh"

#include "backends/cuda/cuda_check.cuh"

namespace tridem::cuda {

StageEvents::StageEvents(cudaStream_t stream) : stream_(stream) {
  every = kSampleEvery;
  shares_of_wall = true;
  for (auto& step : events_)
    for (cudaEvent_t& e : step) TRIDEM_CUDA_CHECK(cudaEventCreate(&e));
}

StageEvents::~StageEvents() {
  for (auto& step : events_)
    for (cudaEvent_t e : step)
      if (e) cudaEventDestroy(e);
}

void StageEvents::begin_step() {
  stage_ = 0;  // a step stopped by a blow-up is recorded over
  TRIDEM_CUDA_CHECK(cudaEventRecord(events_[slot_][0], stream_));
}

void StageEvents::end_stage(Stage stage) {
  stage_of_[slot_][stage_] = stage;
  ++stage_;
  TRIDEM_CUDA_CHECK(cudaEventRecord(events_[slot_][stage_], stream_));
}

void StageEvents::end_step() {
  stages_[slot_] = stage_;
  count_timed_step();
  if (++slot_ == kRingSteps) {
    drain();
    slot_ = 0;
    drained_ = 0;
  }
}

void StageEvents::drain() const {
  if (drained_ == slot_) return;
  // The last event of the last step may have been recorded after the step's own
  // synchronisation: the stream is idle, so this waits for nothing but the event itself.
  TRIDEM_CUDA_CHECK(cudaEventSynchronize(events_[slot_ - 1][stages_[slot_ - 1]]));
  for (int s = drained_; s < slot_; ++s)
    for (int k = 0; k < stages_[s]; ++k) {
      float ms = 0;
      TRIDEM_CUDA_CHECK(cudaEventElapsedTime(&ms, events_[s][k], events_[s][k + 1]));
      seconds_[static_cast<int>(stage_of_[s][k])] += 1e-3 * static_cast<double>(ms);
    }
  drained_ = slot_;
}

StageTimes StageEvents::times() const {
  drain();
  StageTimes t;
  fill(t, seconds_.data());
  t.clock = "CUDA events (shares of the steps' wall time)";
  return t;
}

}  // namespace tridem::cuda
