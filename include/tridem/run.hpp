#pragma once
// A whole run: solver, time loop, output cadence, progress and summary. The app is a thin
// shell over this, and tests drive it too.
#include "tridem/scene.hpp"
#include "tridem/solver.hpp"
#include "tridem/step_observer.hpp"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace tridem {

struct ParticleModel;
struct TimeStep;

/// How to run a scene, besides what the scene says (a command line's overrides of the
/// scene's settings are applied to the scene first: apply_overrides in scene_io.hpp).
struct RunOptions {
  bool force = false;       ///< accept dt above dt_crit
  int threads = 0;          ///< OpenMP threads, 0 = default
  int device = 0;           ///< the cuda backend's GPU (SolverConfig::device)
  ParticleOrder particle_order = ParticleOrder::Auto;  ///< SolverConfig::particle_order
  bool progress = true;     ///< bar on stderr when it is a terminal
  std::FILE* log = stdout;  ///< where the start and summary lines go
  /// A checkpoint to continue from (tridem run --restart): the run goes on from its step
  /// and continues the logs, frames and collections of the output directory.
  std::optional<std::string> restart;
  /// Polled between chunks of steps (a few times a second): once it is non-zero (the
  /// signal number, set by a signal handler), the run stops at the step boundary, writes
  /// its checkpoint and final.csv and returns with RunSummary::interrupted_by set.
  const std::atomic<int>* interrupt = nullptr;
  /// Watches the run (tridem run --live): the time loop asks it before each chunk of steps
  /// how many it may run (its chunks are cut short only when the viewer needs the state
  /// sooner) and calls it after each (it returns at once when no viewer wants a frame).
  /// Not owned; null for none.
  StepObserver* observer = nullptr;
  /// Builds the run's solver in place of make_solver, from the scene, model and time step
  /// the run derived (MPI ranks: src/mpi/mpi_run.cpp); empty = make_solver.
  std::function<std::unique_ptr<Solver>(const Scene&, const ParticleModel&, const TimeStep&,
                                        const SolverConfig&)>
      make_solver;
  /// When the run's set-up began, for the set-up time it reports (tridem run sets it
  /// before reading the scene); unset: when run_scene was called.
  std::optional<std::chrono::steady_clock::time_point> started;
};

/// Where the outputs' wall time of a run went (of RunSummary::output_seconds).
struct OutputSeconds {
  double snapshots = 0;    ///< taking the state (and contacts) from the solver
  double final_files = 0;  ///< final.csv and bodies.csv
  double frame_waits = 0;  ///< waiting for the frame written beside the stepping
  double rest = 0;         ///< logs, measures, checkpoints
};

struct RunSummary {
  std::int64_t steps = 0;      ///< steps run by this call
  std::int64_t last_step = 0;  ///< the step the state is at
  int interrupted_by = 0;      ///< the interrupt's value, 0 if the run finished
  std::string checkpoint;      ///< written on interruption
  std::size_t triangles = 0;
  double seconds = 0;  ///< time-loop wall time, outputs included
  double steps_per_second = 0;
  double triangle_steps_per_second = 0;
  std::string solver;
  StageTimes stages;  ///< the time loop's steps, stage by stage (outputs not included)
  double setup_seconds = 0;   ///< from RunOptions::started to the first step
  double output_seconds = 0;  ///< of `seconds`, spent writing outputs (frames: only the wait)
  OutputSeconds outputs;      ///< output_seconds, part by part
};

/// Runs `scene` to the end (or to an interruption): its settings are the run's (backend,
/// precision, method, steps, output directory); relax_overlaps moves its triangles. Taken
/// by value: a caller done with its scene moves it in (10^7 triangles are some 0.9 GB to
/// copy), one that keeps it passes a copy. Writes its outputs, and checkpoints every
/// [output] checkpoint_every steps. Throws tridem::Error on failure; on a blow-up the last
/// good state is first written to last_good.ckpt and final.csv.
RunSummary run_scene(Scene scene, const RunOptions& options);

/// What `tridem info` prints about a scene.
struct SceneInfo {
  std::size_t triangles = 0, free = 0, fixed = 0, prescribed = 0;
  Vec2d box_lo{}, box_hi{};
  double longest_edge = 0;
  double dt_critical = 0, dt_chosen = 0;
  bool dt_automatic = true;
  std::int64_t steps = 0;            ///< the run's length: [simulation] steps or time / dt
  std::string dt_limit;              ///< what sets dt_critical ("particle 3 pressed ...")
  std::size_t memory_bytes = 0;      ///< estimated memory of a run (solver and host)
  std::size_t gpu_memory_bytes = 0;  ///< GPU memory the cuda backend reserves at start
                                     ///< (0 in a build without CUDA)
  /// Pairs in the run's first list, about: those within the skin at the start (the broad
  /// phase's candidates), which the memory estimates are sized by.
  std::size_t first_list_pairs = 0;
  std::string gpu;                   ///< the GPU found, empty when none is usable
  /// How far apart consecutive free particles lie, in grain sizes on average
  /// (core/numbering_note.hpp: ~1.6 for a scene numbered by place; 0 without two).
  double numbering_distance = 0;
  /// numbering_distance over two id-scrambled particles' distance: near 0 by place, near 1
  /// at random (core/numbering_note.hpp).
  double numbering_spread = 0;
  /// tridem run (--particle-order auto) numbers the particles by place inside the solver
  /// (core/place_numbered_solver: a large scene numbered far apart).
  bool numbered_by_place = false;
};

SceneInfo describe_scene(const Scene& scene);

}  // namespace tridem
