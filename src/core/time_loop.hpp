#pragma once
// The time loop of a run: advances the solver from its current step to the last one in
// chunks, and at each event writes what is due (frames every [output] every steps, log
// rows every energy_every, checkpoints every checkpoint_every). It also owns the two ways a run
// stops early: an interruption (the flag of RunOptions) and a blow-up (RunError from the solver).
#include "core/progress.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/output.hpp"
#include "tridem/run.hpp"
#include "tridem/solver.hpp"
#include "tridem/step_observer.hpp"

#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace tridem {

/// Where a run keeps its states, under its output directory.
struct StateFiles {
  std::filesystem::path checkpoint;  ///< checkpoint.ckpt: periodic, at the end, on interruption
  std::filesystem::path last_good;   ///< last_good.ckpt: the state before a blow-up
  explicit StateFiles(const std::filesystem::path& dir)
      : checkpoint(dir / "checkpoint.ckpt"), last_good(dir / "last_good.ckpt") {}
};

class TimeLoop {
 public:
  /// `out` must outlive the loop; `meta` goes into every checkpoint.
  TimeLoop(Solver& solver, OutputSet& out, const Scene& scene, CheckpointMeta meta,
           const std::atomic<int>* interrupt, bool progress, StepObserver* observer = nullptr);

  /// Waits for a frame in flight (dropping its failure) when it may still use the loop's
  /// contact copy.
  ~TimeLoop();
  TimeLoop(const TimeLoop&) = delete;
  TimeLoop& operator=(const TimeLoop&) = delete;
  /// Writes the outputs of step 0 (a fresh run), or final.csv when a restarted run is
  /// already at its end.
  void start(bool resumed);
  /// Runs to the last step. Returns the interrupting signal, or 0 when the run finished.
  /// On interruption the checkpoint and final.csv hold the step reached; on a blow-up
  /// last_good.ckpt and final.csv hold the last good state, and the RunError says so.
  int run();

  const StateFiles& files() const { return files_; }
  /// Wall time spent in outputs so far: snapshots, logs, checkpoints, final.csv, and the
  /// wait for a frame written beside the stepping.
  double output_seconds() const { return output_seconds_; }
  /// The same, part by part (the rest is output_seconds less the named parts).
  OutputSeconds output_parts() const;

 private:
  /// Advances to `target` unless interrupted; returns the interrupting signal or 0.
  int advance_to(std::int64_t target);
  void advance_chunk(std::int64_t target);
  void write_due(std::int64_t step);
  void emit(std::int64_t step, bool frame, bool log, bool measure);
  bool measure_due_at(std::int64_t step) const;
  /// A checkpoint to `file` and final.csv of the state the solver holds now (no log row
  /// or frame, which an uninterrupted run would not have at this step).
  void keep_state(const std::filesystem::path& file);
  void save_checkpoint(const std::filesystem::path& file);

  Solver& solver_;
  OutputSet& out_;
  const Scene& scene_;
  CheckpointMeta meta_;
  const std::atomic<int>* interrupt_;
  StepObserver* observer_;  ///< the live view, or null
  StateFiles files_;
  ProgressBar bar_;
  std::int64_t last_, every_, log_every_, checkpoint_every_;
  std::vector<std::int64_t> measure_every_;  ///< of each [[measure]]
  std::int64_t chunk_ = 1;
  double seconds_per_step_ = 0;  ///< of the last chunk (the observer sizes its chunks by it)
  Snapshot snap_;
  /// A frame's contacts copied beside the steps (null: taken with the snapshot).
  std::unique_ptr<ContactCopy> contact_copy_;
  Checkpoint checkpoint_;  ///< reused: its arrays keep their capacity between checkpoints
  double output_seconds_ = 0;
  OutputSeconds parts_;  ///< of output_seconds_; its `rest` is filled by output_parts()
};

}  // namespace tridem
