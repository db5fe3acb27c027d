#pragma once
// A copy of a solver's state taken between steps without holding the steps up for long:
// the live view's frames (src/live/, docs/live-view.md). start() runs on the stepping
// thread and only copies (CPU: the arrays into this object's own; CUDA: a device-to-device
// copy on the solver's stream, then a download on a stream of its own into pinned memory);
// finish() runs on another thread, waits for the copy and converts it. The object owns
// every buffer it reads in finish(): it may finish after its solver has gone.
#include "tridem/energy_budget.hpp"
#include "tridem/snapshot.hpp"

#include <memory>

namespace tridem {

class Solver;

class StateCopy {
 public:
  virtual ~StateCopy() = default;
  /// Stepping thread, between two steps: starts copying the current step and time, the
  /// shown fields (the walls' forces included, as in a snapshot), the bonds' damage and
  /// the energy budget. Not again before finish() has returned.
  virtual void start() = 0;
  /// Any thread, once after each start(): waits for the copy, then writes `out`'s step,
  /// time, shown fields and bond_damage (sized here; the rest of `out` is left alone) and
  /// returns the energy budget of that step (Solver::energy() then, to the bit).
  virtual EnergyBudget finish(Snapshot& out) = 0;
};

/// The copy every backend can give: start() takes a whole Solver::snapshot and the energy
/// on the calling thread (synchronous; the fallback of backends without a faster one).
std::unique_ptr<StateCopy> make_snapshot_copy(const Solver& solver);

}  // namespace tridem
