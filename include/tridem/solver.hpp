#pragma once
// The solver interface: one object per run, holding the state on its backend. The step is
// a fixed sequence of stages (see Stage); backends differ only in how they schedule it.
#include "tridem/energy_budget.hpp"
#include "tridem/scene.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver_state.hpp"

#include <cstdint>
#include <memory>
#include <string>

namespace tridem {

/// The stages of one step, in the order they run.
enum class Stage {
  Geometry,    ///< vertices and bounding boxes from the poses
  BroadPhase,  ///< pairs (cell grid or all pairs: boxes overlap; single-domain: every pair
               ///< through the contact test), contact history carried over
  PairForces,  ///< exact overlap test and potential contact force of each candidate pair
  Accumulate,  ///< sum of the pair forces on each particle
  Integrate,   ///< symplectic Euler, prescribed motions, blow-up check
};

/// How to run a scene on this machine: what the scene cannot say because it depends on
/// the machine, not on the simulation. Backend, precision, method and every other setting
/// come from the Scene alone (after the command line's overrides: apply_overrides).
struct SolverConfig {
  /// OpenMP threads of the openmp backend; 0 = the runtime's default. Applied to the
  /// solver's own parallel regions only: the caller's OpenMP settings are left as they were.
  int threads = 0;
  /// The GPU of the cuda backend, an index below cuda_device_count() (0 = the first, as
  /// CUDA numbers them, after CUDA_VISIBLE_DEVICES); other backends refuse anything else.
  int device = 0;
  bool force = false;  ///< run even with dt above dt_crit
};

class Solver {
 public:
  virtual ~Solver() = default;
  /// Advances `steps` steps. Throws RunError naming the step and particle on blow-up;
  /// the state is then the last good one.
  virtual void advance(std::int64_t steps) = 0;
  /// Copies the state (and the contacts of the last step when asked) to the host.
  virtual void snapshot(Snapshot& out, bool with_contacts) const = 0;
  /// Copies what a restart needs (state, step, time, contact history) to the host, under
  /// the contract of solver_state.hpp. Allocates: call it between steps, not inside them.
  virtual void save_state(SolverState& out) const = 0;
  /// Replaces the state by `in` (from save_state of a solver of the same scene, backend
  /// and precision), so that the next advance() continues that run exactly. Throws
  /// tridem::Error (via validate_solver_state) on a state that does not fit this solver.
  virtual void load_state(const SolverState& in) = 0;
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
