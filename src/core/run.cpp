#include "tridem/run.hpp"

#include "core/initial_overlaps.hpp"
#include "core/numbering_note.hpp"
#include "core/output_notes.hpp"
#include "core/place_numbered_solver.hpp"
#include "core/solver_factory.hpp"
#include "core/stage_report.hpp"
#include "core/time_loop.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <algorithm>
#include <chrono>
#include <fmt/format.h>
#include <future>

namespace tridem {

namespace {

namespace fs = std::filesystem;

/// The state the run starts from: the scene's, or that of `--restart`.
std::optional<ResumePoint> restore(Solver& solver, const Scene& scene, const CheckpointMeta& run,
                                   const RunOptions& options) {
  if (!options.restart) return std::nullopt;
  const fs::path file = *options.restart;
  const Checkpoint c = read_checkpoint(file);
  check_checkpoint_fits(c, file, scene, run);
  if (c.state.step > scene.simulation.steps)
    throw RunError(fmt::format("{}: checkpoint at step {} is past the end of the run (steps "
                               "= {}); raise [simulation] steps or give --steps",
                               file.string(), c.state.step, scene.simulation.steps));
  solver.load_state(c.state);
  return ResumePoint{c.state.step, c.state.time};
}

void print_start(std::FILE* log, const Solver& solver, const TimeStep& ts, std::size_t free,
                 Backend requested, std::int64_t last) {
  fmt::print(log, "tridem {}: {} triangle{} ({} free), solver {}{}\n", TRIDEM_VERSION,
             solver.size(), solver.size() == 1 ? "" : "s", free, solver.description(),
             requested == Backend::Auto ? " (picked by backend = auto)" : "");
  fmt::print(log, "dt = {:.6g} s = {:.3g} x dt_crit ({:.6g} s){}, {} steps to t = {:.6g} s\n",
             solver.dt(), solver.dt() / ts.critical, ts.critical, ts.automatic ? ", automatic" : "",
             last, static_cast<double>(last) * solver.dt());
  // What sets dt_crit, so that a user sees which contact (a thin wall?) costs the steps.
  if (const std::string by = ts.limit.describe(); !by.empty())
    fmt::print(log, "dt_crit set by {}\n", by);
}

/// The set-up's parts: each lap from the end of the last one (the first from the start).
class SetupClock {
 public:
  explicit SetupClock(std::chrono::steady_clock::time_point start) : last_(start) {}
  void lap(const char* what,
           std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now()) {
    laps_ += fmt::format("{}{} {:.3g} s", laps_.empty() ? "" : ", ", what,
                         std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }
  /// "scene 0.41 s, model 0.1 s, ..."
  const std::string& laps() const { return laps_; }

 private:
  std::chrono::steady_clock::time_point last_;
  std::string laps_;
};

void print_relaxation(std::FILE* log, const RelaxReport& r) {
  if (r.pairs == 0) {
    fmt::print(log, "relax_overlaps: no overlapping triangles\n");
    return;
  }
  fmt::print(log,
             "relax_overlaps: {} overlapping pair{} (deepest {:.6g} m) pushed apart in {} "
             "iteration{}: {} particle{} moved (first id {}), by at most {:.6g} m; velocities "
             "unchanged\n",
             r.pairs, r.pairs == 1 ? "" : "s", r.deepest, r.iterations,
             r.iterations == 1 ? "" : "s", r.moved, r.moved == 1 ? "" : "s", r.first_moved,
             r.largest_move);
}

}  // namespace

RunSummary run_scene(Scene scene, const RunOptions& options) {
  const auto setup_start = options.started.value_or(std::chrono::steady_clock::now());
  SetupClock clock(setup_start);
  clock.lap("scene");
  // Before anything is derived from the positions (a restart relaxes the same way, so its
  // scene fingerprint matches).
  std::optional<RelaxReport> relaxed;
  if (scene.simulation.relax_overlaps) relaxed = relax_initial_overlaps(scene);
  // The checkpoints' scene fingerprint is one serial pass over every triangle (some 0.1 s
  // per 10^6): hashed on a thread of its own while the model, the time step and the solver
  // are built, which only read the triangles (set-up of a 10^7 run, issue 12).
  std::future<std::uint64_t> fingerprint =
      std::async(std::launch::async, [&scene] { return scene_fingerprint(scene); });

  SolverConfig config;
  config.threads = options.threads;
  config.device = options.device;
  config.particle_order = options.particle_order;
  config.force = options.force;
  config.thread_use = ThreadUse::Measured;  // threads only where they pay on these cores
  const ParticleModel model = build_particle_model(scene);
  clock.lap("model");
  const TimeStep ts = estimate_time_step(scene, model);
  scene.simulation.steps = steps_to_reach(scene.simulation, ts.chosen);
  clock.lap("time step");
  const auto solver = options.make_solver ? options.make_solver(scene, model, ts, config)
                                          : make_solver(scene, model, ts, config);
  clock.lap("solver");
  // MPI ranks (options.make_solver) keep the scene's order: they are not renumbered.
  const bool numbered_by_place =
      !options.make_solver && numbers_by_place(scene, model, config.particle_order);
  const auto free =
      static_cast<std::size_t>(std::count(model.motion.begin(), model.motion.end(), Motion::Free));
  // What the checkpoints of this run record, and what a restart must match.
  const CheckpointMeta meta{scene.simulation.precision, fingerprint.get(),
                            physics_settings(scene, ts.chosen)};
  const std::optional<ResumePoint> resume = restore(*solver, scene, meta, options);

  const std::int64_t last = scene.simulation.steps;
  const std::int64_t first = solver->step();
  std::FILE* log = options.log;
  if (log) {
    print_start(log, *solver, ts, free, scene.simulation.backend, last);
    if (relaxed) print_relaxation(log, *relaxed);
    if (const std::string note =
            output_notes(scene.output, model.size(), scene.simulation.precision);
        !note.empty())
      fmt::print(log, "{}", note);
    if (const std::string note = numbering_note(model, numbered_by_place); !note.empty())
      fmt::print(log, "{}", note);
    if (resume)
      fmt::print(log, "continuing from {} at step {} (t = {:.6g} s)\n", *options.restart,
                 resume->step, resume->time);
    std::fflush(log);
  }

  OutputSet out(scene.output, scene.output.dir, scene.output.vtk_format(), resume);
  TimeLoop loop(*solver, out, scene, meta, options.interrupt, options.progress, options.observer);
  if (options.observer) options.observer->run_starting(*solver);
  RunSummary summary;
  const auto start = std::chrono::steady_clock::now();
  summary.setup_seconds = std::chrono::duration<double>(start - setup_start).count();
  clock.lap("the rest", start);
  loop.start(resume.has_value());
  try {
    summary.interrupted_by = loop.run();
  } catch (...) {
    if (options.observer) options.observer->run_ended(*solver);
    throw;
  }
  if (options.observer) options.observer->run_ended(*solver);
  if (summary.interrupted_by) summary.checkpoint = loop.files().checkpoint.string();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  summary.steps = solver->step() - first;
  summary.last_step = solver->step();
  summary.triangles = solver->size();
  summary.seconds = seconds;
  summary.steps_per_second = seconds > 0 ? static_cast<double>(summary.steps) / seconds : 0;
  summary.triangle_steps_per_second =
      summary.steps_per_second * static_cast<double>(summary.triangles);
  summary.solver = solver->description();
  summary.stages = solver->stage_times();
  summary.output_seconds = loop.output_seconds();
  summary.outputs = loop.output_parts();
  if (log) {
    fmt::print(log,
               "{}: {} steps in {:.3f} s: {:.4g} steps/s, {:.4g} triangle-steps/s; "
               "outputs in {}\n",
               summary.interrupted_by ? "interrupted" : "done", summary.steps, seconds,
               summary.steps_per_second, summary.triangle_steps_per_second, scene.output.dir);
    // Where a large run's time beyond its steps goes (issue 12: set-up and final outputs).
    const double stepping = std::max(0.0, seconds - summary.output_seconds);
    fmt::print(log,
               "wall time: set-up {:.3f} s ({}), stepping {:.3f} s ({:.4g} triangle-steps/s), "
               "outputs {:.3f} s (snapshots {:.3g} s, waiting for frames {:.3g} s, final.csv "
               "and bodies.csv {:.3g} s, the rest {:.3g} s)\n",
               summary.setup_seconds, clock.laps(), stepping,
               stepping > 0 ? static_cast<double>(summary.steps * summary.triangles) / stepping
                            : 0.0,
               summary.output_seconds, summary.outputs.snapshots, summary.outputs.frame_waits,
               summary.outputs.final_files, summary.outputs.rest);
    if (const std::string stats = solver->statistics(); !stats.empty())
      fmt::print(log, "{}: {}\n", solver->description(), stats);
    fmt::print(log, "{}", stage_table(summary.stages));
    std::fflush(log);
  }
  return summary;
}

}  // namespace tridem
