#pragma once
// The solver interface: one object per run, holding the state on its backend. The step is
// a fixed sequence of stages (see Stage); backends differ only in how they schedule it.
#include "tridem/contact_copy.hpp"
#include "tridem/energy_budget.hpp"
#include "tridem/scene.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver_state.hpp"
#include "tridem/state_copy.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace tridem {

// tridem/checkpoint.hpp (C++20: declared here for the CUDA sources, compiled as C++17).
struct Checkpoint;
struct CheckpointMeta;

/// The stages of one step. Each backend runs them through run_stage() in the order of its
/// pipeline (core/stage_pipeline.hpp), which times each one; a stage that a backend fuses
/// into another one's kernel is not in its pipeline and reports no time (ARCHITECTURE.md,
/// "The stages of a step").
enum class Stage {
  Geometry,    ///< vertices and bounding boxes from the poses
  PairList,    ///< broad phase: the pairs (cell grid or all pairs: boxes overlap;
               ///< single-domain, decomposition: through the contact test), their contact
               ///< history carried over, the reverse index
  PairForces,  ///< exact overlap test and contact force of each listed pair; too deep a
               ///< pair stops the run
  Gather,      ///< the sum of its pair forces on each particle, in a fixed order
  Check,       ///< the runaway test of every particle's step, before anything is written
  Integrate,   ///< symplectic Euler and prescribed motions written, the step's energy added
};
inline constexpr int kStageCount = 6;

/// "geometry", "pair list", "pair forces", "gather", "check", "integrate".
const char* stage_name(Stage stage);

/// Wall time spent in each stage over the steps completed so far (a step stopped by a
/// blow-up is not counted). CPU: steady_clock; CUDA: GPU events between the stages.
struct StageTimes {
  double seconds[kStageCount] = {};  ///< over all completed steps (scaled when sampled)
  std::int64_t steps = 0;
  std::int64_t timed_steps = 0;  ///< the steps whose stages were timed (a clock may sample)
  const char* clock = "";  ///< how the times were taken, for the report
  /// Per fused stage, the stage whose time includes it (its own index when not fused).
  int fused_into[kStageCount] = {0, 1, 2, 3, 4, 5};

  double total() const;
};

/// How to run a scene on this machine: what the scene cannot say because it depends on
/// the machine, not on the simulation. Backend, precision, method and every other setting
/// come from the Scene alone (after the command line's overrides: apply_overrides).
/// How the openmp backend uses its threads (backends/cpu/thread_choice.hpp).
enum class ThreadUse {
  Always,       ///< every step on the threads (benchmarks, and tests of the parallel path)
  Measured,     ///< each step the faster way, threads or one, timed during the run
  Alternating,  ///< threads and one in turn, step by step (tests: both ways give the same bits)
};

/// The order in which a solver keeps and steps the particles (docs/performance.md, "The
/// particles' order"). Whichever it picks, everything it gives (snapshots, states,
/// checkpoints, messages) names the particles by the scene's ids.
enum class ParticleOrder {
  Auto,   ///< by place when a large scene is numbered far from where its particles lie
  Scene,  ///< the scene's order
  Place,  ///< the free particles along a curve through their centroids; walls stay put
};

struct SolverConfig {
  /// OpenMP threads of the openmp backend; 0 = the runtime's default. Applied to the
  /// solver's own parallel regions only: the caller's OpenMP settings are left as they were.
  int threads = 0;
  /// The GPU of the cuda backend, an index below cuda_device_count() (0 = the first, as
  /// CUDA numbers them, after CUDA_VISIBLE_DEVICES); other backends refuse anything else.
  int device = 0;
  bool force = false;  ///< run even with dt above dt_crit
  /// Always for a solver made in code; tridem run measures (core/run.cpp): on cores that
  /// other programs share, threads can cost more than they give.
  ThreadUse thread_use = ThreadUse::Always;
  /// The cuda backend launches each step before it has read the last one's status (the
  /// same results; docs/performance.md, "Run-ahead"). false: every step waits for the one
  /// before it, as before run-ahead (tests and benchmarks compare both).
  bool gpu_run_ahead = true;
  /// The cuda backend compacts and downloads a frame's contact network this many rows at a
  /// time, so that a frame's GPU scratch is bounded whatever its contacts; 0 = the default,
  /// 2^22 rows (168 MB in float). The same contacts either way (tests use a small one).
  std::size_t gpu_contact_rows_per_copy = 0;
  /// Auto numbers by place (bodies as wholes) a scene of at least 10^5
  /// particles whose consecutive ids lie over 20 grain sizes apart (core/numbering_note):
  /// such a run steps at up to twice the rate. Its results then differ from the scene
  /// order's in rounding (sums in another order); Scene keeps them bit for bit.
  ParticleOrder particle_order = ParticleOrder::Auto;
  /// Under Auto and Place, a solver of at least 10^5 particles looks at its order every
  /// this many steps (at the steps that are multiples of it) and numbers its particles by
  /// place again when the neighbours of consecutive ones have scattered in memory
  /// (core/neighbour_blocks.hpp), as a flow mixes the grains; 0 = never. The looks are a function
  /// of the step and the state, so a run is reproduced bit for bit, and its checkpoints carry the
  /// order.
  std::int64_t order_check_steps = 10000;
};

class Solver {
 public:
  virtual ~Solver() = default;
  /// Advances `steps` steps. Throws RunError naming the step and particle on blow-up;
  /// the state is then the last good one.
  virtual void advance(std::int64_t steps) = 0;
  /// Copies the state (and the contacts of the last step when asked) to the host.
  virtual void snapshot(Snapshot& out, bool with_contacts) const = 0;
  /// A copy of the state for the live view (tridem/state_copy.hpp), made once per run: it
  /// allocates its buffers here. The default takes snapshots (make_snapshot_copy); the CPU
  /// solvers copy their arrays, the CUDA solver downloads on a stream of its own.
  virtual std::unique_ptr<StateCopy> make_state_copy() const { return make_snapshot_copy(*this); }
  /// A copy of the contacts for frames (tridem/contact_copy.hpp), made once per run; null
  /// (the default) when a snapshot with contacts costs the stepping thread little, as on
  /// the CPU: the time loop then takes them with the snapshot. The CUDA solver's compacts
  /// and downloads them beside the steps.
  virtual std::unique_ptr<ContactCopy> make_contact_copy() const { return nullptr; }
  /// Copies what a restart needs (state, step, time, contact history) to the host, under
  /// the contract of solver_state.hpp. Allocates: call it between steps, not inside them.
  virtual void save_state(SolverState& out) const = 0;
  /// Replaces the state by `in` (from save_state of a solver of the same scene, backend
  /// and precision), so that the next advance() continues that run exactly. Throws
  /// tridem::Error (via validate_solver_state) on a state that does not fit this solver.
  virtual void load_state(const SolverState& in) = 0;
  /// Writes the state as the checkpoint `file` with `meta`, atomically (tridem/checkpoint.hpp).
  /// `scratch` is the caller's, kept between checkpoints so that its arrays are reused. The
  /// default saves the state into it and writes the file from this process; the ranks of an
  /// MPI run each write their part of the file, side by side (mpi/parallel_checkpoint.hpp).
  virtual void save_checkpoint(const std::filesystem::path& file, const CheckpointMeta& meta,
                               Checkpoint& scratch) const;
  /// The energy budget at the current step (energy.csv): the elastic energy of the
  /// contacts of the last step (0 before the first) and the cumulative dissipations and
  /// wall work since step 0. Reduces per-particle sums: call it at logging steps.
  virtual EnergyBudget energy() const = 0;
  virtual std::int64_t step() const = 0;
  virtual double time() const = 0;
  virtual double dt() const = 0;
  virtual std::size_t size() const = 0;
  /// e.g. "openmp (2 threads), double, grid"
  virtual std::string description() const = 0;
  /// The time each stage took over the steps advanced so far. Cheap: a backend collects
  /// the times as it goes and adds them up only here.
  virtual StageTimes stage_times() const = 0;
  /// Stage timing is on from the start; off, a step takes no clock readings at all (the
  /// benchmark measures what timing costs this way).
  virtual void set_stage_timing(bool on) = 0;
  /// What the solver did so far, for the run's summary (e.g. how often the CUDA pair list
  /// was rebuilt); empty when there is nothing to say.
  virtual std::string statistics() const { return {}; }
};

/// A solver of the scene on the backend, precision and method of its [simulation] (Auto
/// picks the fastest available and says so in description()). Throws SceneError /
/// RunError for a scene that cannot run.
std::unique_ptr<Solver> make_solver(const Scene& scene, const SolverConfig& config);

/// The concrete backend Auto resolves to on this machine.
Backend resolve_backend(Backend requested);

}  // namespace tridem
