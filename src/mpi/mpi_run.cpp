#include "mpi/mpi_run.hpp"

#include "mpi/agreement.hpp"
#include "mpi/mpi_solver.hpp"
#include "tridem/error.hpp"

#include <atomic>
#include <optional>

namespace tridem::mpi {

namespace {

/// How a rank other than 0 leaves run_scene once it has served rank 0 to the end.
struct Served {
  bool ok;
};

}  // namespace

int run_on_ranks(const std::function<Scene()>& read, RunOptions options,
                 const std::function<int(const RunSummary&)>& report) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  // What the time loop polls: any rank's signal, as the ranks agreed at the last step.
  std::atomic<int> agreed_interrupt{0};
  const std::atomic<int>* os_interrupt = options.interrupt;
  options.interrupt = &agreed_interrupt;
  if (rank != 0) {
    options.log = nullptr;
    options.progress = false;
  }
  bool built = false;
  options.make_solver = [&](const Scene& scene, const ParticleModel& model, const TimeStep& ts,
                            const SolverConfig&) -> std::unique_ptr<Solver> {
    built = true;  // from here on, failures are agreed inside the solver
    std::unique_ptr<Solver> solver;
    if (scene.simulation.precision == Precision::Float)
      solver = std::make_unique<MpiSolver<float>>(MPI_COMM_WORLD, scene, model, ts, os_interrupt,
                                                  &agreed_interrupt);
    else
      solver = std::make_unique<MpiSolver<double>>(MPI_COMM_WORLD, scene, model, ts, os_interrupt,
                                                   &agreed_interrupt);
    if (rank == 0) return solver;
    const bool ok = scene.simulation.precision == Precision::Float
                        ? static_cast<MpiSolver<float>&>(*solver).serve()
                        : static_cast<MpiSolver<double>&>(*solver).serve();
    throw Served{ok};
  };
  try {
    const RunSummary summary = run_scene(read(), options);
    return report(summary);
  } catch (const Served& s) {
    return s.ok ? 0 : 1;
  } catch (const std::exception& e) {
    if (!built) {
      // Before the solver: the others wait in its first agreement; stop them with the
      // lowest failing rank's message (every rank reads the same scene, so usually each
      // has the same one).
      const std::optional<std::string> m = agree(MPI_COMM_WORLD, std::string(e.what()));
      if (rank == 0) throw Error(m.value_or(e.what()));
      return 1;
    }
    if (rank == 0) throw;
    return 1;
  }
}

}  // namespace tridem::mpi
