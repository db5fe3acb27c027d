#pragma once
// `tridem run` on the ranks of MPI_COMM_WORLD (docs/scaling.md): every rank reads the
// scene and derives the run as one rank would (relaxation, model, time step); rank 0 then
// runs the time loop and writes every output, the others serve it (mpi_solver.hpp).
// Failures are agreed: a rank that cannot read the scene, a refusal, a blow-up on any
// rank, stop every rank, and only rank 0 prints the message.
#include "tridem/run.hpp"
#include "tridem/scene.hpp"

#include <functional>

namespace tridem::mpi {

/// Runs the scene `read` gives on every rank. On rank 0, returns `report`'s exit code of
/// the summary, or throws the agreed tridem::Error for the app to print; other ranks
/// return 0, or 1 after a failure (they print nothing).
int run_on_ranks(const std::function<Scene()>& read, RunOptions options,
                 const std::function<int(const RunSummary&)>& report);

}  // namespace tridem::mpi
