#pragma once
// One output format of a run (frames, a contact network, a log, final.csv) behind one
// interface: OutputSet holds the list make_writers() returns and calls every writer at
// each event, and the take-over of the output directory (a fresh run removing an earlier
// run's files, a restarted one cutting its files back to the checkpoint) asks every
// writer for its own files. A new format is a writer and a line in make_writers().
#include "tridem/energy_budget.hpp"
#include "tridem/output.hpp"
#include "tridem/scene.hpp"
#include "tridem/snapshot.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace tridem::io {

/// What a logging step gives the logs besides the snapshot.
struct LogInputs {
  Vec2d gravity{};
  EnergyBudget budget;
};

class OutputWriter {
 public:
  virtual ~OutputWriter() = default;
  /// Takes over the output directory: a fresh run (no `resume`) removes this format's
  /// files of an earlier run there; a restarted one keeps them up to the resume point
  /// and removes what came after, which it will write again.
  virtual void start(const std::optional<ResumePoint>& resume) = 0;
  /// Every [output] every steps. It may run on the output thread (OutputSet::
  /// write_frame_beside) while the other calls run on the caller's: a writer that writes
  /// frames shares no state with the calls of other writers.
  virtual void frame(const Snapshot&) {}
  virtual void log(const Snapshot&, const LogInputs&) {}  ///< every energy_every steps
  /// At every step where some [[measure]] is due (measure_due), and only there; the
  /// snapshot holds the contacts. `last_step`: the run's last step.
  virtual void measure(const Snapshot&, bool /*last_step*/) {}
  virtual void final_state(const Snapshot&) {}            ///< the state a run ends or stops with
};

/// Every output format of a run into `dir`, in the order they write.
std::vector<std::unique_ptr<OutputWriter>> make_writers(const OutputSettings& settings,
                                                        const std::filesystem::path& dir,
                                                        VtkFormat format);

/// Creates `dir` and its parents; throws RunError naming it and the reason when it cannot
/// (an existing file of that name included).
void make_directory(const std::filesystem::path& dir);

}  // namespace tridem::io
