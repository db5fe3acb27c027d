#pragma once
// What the split step of an MPI rank did (docs/scaling.md, "Overlap"): the ghost exchange
// in flight while the rank computes the pairs of its own particles. Plain C++, counted by
// the CPU solver (CpuSolver::set_ghost_hooks) and summed over a run's plans by MpiSolver.
#include <cstdint>

namespace tridem {

struct GhostOverlapCounts {
  std::int64_t steps = 0;           ///< split steps run
  std::int64_t overlapped = 0;      ///< own pairs computed while the ghosts were in flight
  std::int64_t rebuilt = 0;         ///< steps that built the list (the ghosts taken first)
  std::int64_t discarded = 0;       ///< of those, built after a ghost left its build box
  std::int64_t ghost_contacts = 0;  ///< steps with a touching pair on a ghost

  GhostOverlapCounts& operator+=(const GhostOverlapCounts& o) {
    steps += o.steps;
    overlapped += o.overlapped;
    rebuilt += o.rebuilt;
    discarded += o.discarded;
    ghost_contacts += o.ghost_contacts;
    return *this;
  }
};

}  // namespace tridem
