#include "core/time_loop.hpp"

#include "core/chunk_size.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <chrono>
#include <fmt/format.h>
#include <utility>

namespace tridem {

namespace {

/// The next multiple of `every` after `step`, or `last` if that comes first (or every = 0).
std::int64_t next_multiple(std::int64_t step, std::int64_t every, std::int64_t last) {
  if (every <= 0) return last;
  return std::min(last, (step / every + 1) * every);
}

bool is_due(std::int64_t step, std::int64_t every) { return every > 0 && step % every == 0; }

/// Adds the wall time of its scope to `total`.
class OutputClock {
 public:
  explicit OutputClock(double& total) : total_(total), t0_(std::chrono::steady_clock::now()) {}
  ~OutputClock() {
    total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }
  OutputClock(const OutputClock&) = delete;
  OutputClock& operator=(const OutputClock&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace

TimeLoop::TimeLoop(Solver& solver, OutputSet& out, const Scene& scene, CheckpointMeta meta,
                   const std::atomic<int>* interrupt, bool progress, StepObserver* observer)
    : solver_(solver),
      out_(out),
      scene_(scene),
      meta_(std::move(meta)),
      interrupt_(interrupt),
      observer_(observer),
      files_(scene.output.dir),
      bar_(scene.simulation.steps, progress && is_terminal(stderr)),
      last_(scene.simulation.steps),
      every_(scene.output.every),
      log_every_(scene.output.log_every()),
      checkpoint_every_(scene.output.checkpoint_every) {
  for (const MeasureSpec& m : scene.output.measures)
    measure_every_.push_back(scene.output.measure_every(m));
  if (every_ > 0 && scene.output.contacts) contact_copy_ = solver.make_contact_copy();
}

// The frame thread may still be appending the contact copy's rows (a failure elsewhere
// left the loop): it must be done before the copy goes. Its own failure is dropped here.
TimeLoop::~TimeLoop() {
  if (!contact_copy_) return;
  try {
    out_.finish_frames();
  } catch (...) {  // NOLINT(bugprone-empty-catch): an error already on its way out wins
  }
}

void TimeLoop::start(bool resumed) {
  const OutputClock clock(output_seconds_);
  if (!resumed) {
    const std::int64_t step = solver_.step();
    emit(step, every_ > 0 && (is_due(step, every_) || step == last_), true, measure_due_at(step));
  } else if (solver_.step() == last_) {  // nothing left to run
    {
      const OutputClock part(parts_.snapshots);
      solver_.snapshot(snap_, false);
    }
    const OutputClock part(parts_.final_files);
    out_.write_final(snap_);
  }
}

int TimeLoop::run() {
  int signal = 0;
  while (solver_.step() < last_ && signal == 0) {
    const std::int64_t step = solver_.step();
    std::int64_t target =
        std::min({next_multiple(step, every_, last_), next_multiple(step, log_every_, last_),
                  next_multiple(step, checkpoint_every_, last_)});
    for (std::int64_t every : measure_every_)
      target = std::min(target, next_multiple(step, every, last_));
    signal = advance_to(target);
    if (signal == 0) write_due(solver_.step());
  }
  bar_.finish();
  const OutputClock clock(output_seconds_);
  if (signal != 0) keep_state(files_.checkpoint);
  // The run is done when its last frame is on disk (or has failed, which throws here).
  const OutputClock part(parts_.frame_waits);
  out_.finish_frames();
  return signal;
}

OutputSeconds TimeLoop::output_parts() const {
  OutputSeconds p = parts_;
  p.rest = std::max(0.0, output_seconds_ - p.snapshots - p.final_files - p.frame_waits);
  return p;
}

int TimeLoop::advance_to(std::int64_t target) {
  while (solver_.step() < target) {
    if (interrupt_ && interrupt_->load() != 0) return interrupt_->load();
    advance_chunk(target);
    bar_.update(solver_.step());
  }
  return 0;
}

// Chunks of 0.05 to 0.2 s (chunk_size.hpp): the progress bar moves without a clock read
// in every step, and an interruption is seen within a fraction of a second. A watched run
// keeps them while its observer has nothing to do, and cuts one short where the observer
// says (a frame due, a client watching, a pause: steps_before_look).
void TimeLoop::advance_chunk(std::int64_t target) {
  std::int64_t steps = std::min(chunk_, target - solver_.step());
  if (observer_)
    steps =
        std::clamp<std::int64_t>(observer_->steps_before_look(steps, seconds_per_step_), 1, steps);
  const auto t0 = std::chrono::steady_clock::now();
  double seconds = 0;
  try {
    solver_.advance(steps);
    // The solver's time only: a viewer's pause must not shrink the chunks.
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (observer_) observer_->after_advance(solver_, interrupt_);
  } catch (const RunError& e) {
    // A blow-up: the solver holds the last good state; keep it for diagnosis or a restart.
    bar_.finish();
    keep_state(files_.last_good);
    throw RunError(fmt::format("{}\nthe last good state (step {}) is in {} (continue from it "
                               "with --restart once the cause is fixed) and {}",
                               e.what(), solver_.step(), files_.last_good.string(),
                               (out_.dir() / "final.csv").string()));
  }
  seconds_per_step_ = seconds / static_cast<double>(steps);
  chunk_ = next_chunk(chunk_, steps, seconds);
}

void TimeLoop::write_due(std::int64_t step) {
  const OutputClock clock(output_seconds_);
  const bool frame = every_ > 0 && (is_due(step, every_) || step == last_);
  const bool log = is_due(step, log_every_) || step == last_;
  const bool measure = measure_due_at(step);
  if (frame || log || measure) emit(step, frame, log, measure);
  if (is_due(step, checkpoint_every_) || (checkpoint_every_ > 0 && step == last_))
    save_checkpoint(files_.checkpoint);
}

bool TimeLoop::measure_due_at(std::int64_t step) const {
  for (std::int64_t every : measure_every_)
    if (measure_due(every, step, step == last_)) return true;
  return false;
}

void TimeLoop::emit(std::int64_t step, bool frame, bool log, bool measure) {
  // Frames take the contacts when [output] contacts asks for them (the contact files and
  // the frames' per-grain stress come from them); a measure always does. Without them a
  // frame is the state alone: on the GPU the contacts are the larger part of a download,
  // and a frame's are copied beside the steps (ContactCopy) unless a measure needs them now.
  const bool frame_contacts = frame && scene_.output.contacts;
  ContactCopy* beside = frame_contacts && !measure ? contact_copy_.get() : nullptr;
  if (beside) {  // the copy's buffer is the previous frame's until that frame is written
    const OutputClock part(parts_.frame_waits);
    out_.finish_frames();
  }
  {
    const OutputClock part(parts_.snapshots);
    solver_.snapshot(snap_, (frame_contacts && !beside) || measure);
    if (beside) beside->start();
  }
  if (log) out_.log(snap_, scene_.simulation.gravity, solver_.energy());
  if (measure) out_.measure(snap_, step == last_);
  if (step == last_) {
    const OutputClock part(parts_.final_files);
    out_.write_final(snap_);
  }
  // Last: the frame is written beside the next steps and takes snap_'s contents with it.
  if (frame) {
    const OutputClock part(parts_.frame_waits);
    out_.write_frame_beside(snap_, beside);
  }
}

void TimeLoop::keep_state(const std::filesystem::path& file) {
  save_checkpoint(file);
  solver_.snapshot(snap_, false);
  out_.write_final(snap_);
}

void TimeLoop::save_checkpoint(const std::filesystem::path& file) {
  solver_.save_checkpoint(file, meta_, checkpoint_);
}

}  // namespace tridem
