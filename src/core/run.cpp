#include "tridem/run.hpp"

#include "core/progress.hpp"
#include "core/solver_factory.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <algorithm>
#include <chrono>
#include <fmt/format.h>

namespace tridem {

namespace {

namespace fs = std::filesystem;

/// The next multiple of `every` after `step`, or `last` if that comes first (or every = 0).
std::int64_t next_multiple(std::int64_t step, std::int64_t every, std::int64_t last) {
  if (every <= 0) return last;
  return std::min(last, (step / every + 1) * every);
}

bool is_due(std::int64_t step, std::int64_t every) { return every > 0 && step % every == 0; }

/// The checkpoint of a run: written every checkpoint_every steps, at the end of the run when
/// checkpoints are on, and when the run is interrupted.
fs::path checkpoint_file(const Scene& scene) { return fs::path(scene.output.dir) / "checkpoint.ckpt"; }
/// The last good state before a blow-up, kept apart so the periodic checkpoint survives.
fs::path last_good_file(const Scene& scene) { return fs::path(scene.output.dir) / "last_good.ckpt"; }

void save_checkpoint(const Solver& solver, Precision precision, std::uint64_t scene_hash,
                     const fs::path& file, Checkpoint& scratch) {
  solver.save_state(scratch.state);
  scratch.meta = {precision, scene_hash};
  write_checkpoint(file, scratch);
}

/// The state the run starts from: the scene's, or that of `--restart`.
std::optional<ResumePoint> restore(Solver& solver, const Scene& scene, Precision precision,
                                   const RunOptions& options) {
  if (!options.restart) return std::nullopt;
  const fs::path file = *options.restart;
  const Checkpoint c = read_checkpoint(file);
  check_checkpoint_fits(c, file, scene, precision);
  if (c.state.step > scene.simulation.steps)
    throw RunError(fmt::format("{}: checkpoint at step {} is past the end of the run (steps "
                               "= {}); raise [simulation] steps or give --steps",
                               file.string(), c.state.step, scene.simulation.steps));
  solver.load_state(c.state);
  return ResumePoint{c.state.step, c.state.time};
}

void print_start(std::FILE* log, const Solver& solver, const TimeStep& ts, std::size_t free,
                 const SolverConfig& config, std::int64_t last) {
  fmt::print(log, "tridem {}: {} triangle{} ({} free), solver {}{}\n", TRIDEM_VERSION,
             solver.size(), solver.size() == 1 ? "" : "s", free, solver.description(),
             config.backend == Backend::Auto ? " (picked by backend = auto)" : "");
  fmt::print(log, "dt = {:.6g} s = {:.3g} x dt_crit ({:.6g} s){}, {} steps to t = {:.6g} s\n",
             solver.dt(), solver.dt() / ts.critical, ts.critical,
             ts.automatic ? ", automatic" : "", last, static_cast<double>(last) * solver.dt());
}

std::string blow_up_message(const RunError& e, std::int64_t good_step, const Scene& scene) {
  return fmt::format("{}\nthe last good state (step {}) is in {} (continue from it with "
                     "--restart once the cause is fixed) and {}",
                     e.what(), good_step, last_good_file(scene).string(),
                     (fs::path(scene.output.dir) / "final.csv").string());
}

}  // namespace

RunSummary run_scene(const Scene& input, const RunOptions& options) {
  Scene scene = input;
  if (options.out_dir) scene.output.dir = *options.out_dir;
  if (options.backend) scene.simulation.backend = *options.backend;
  if (options.steps) scene.simulation.steps = *options.steps;

  SolverConfig config;
  config.backend = scene.simulation.backend;
  config.precision = scene.simulation.precision;
  config.method = scene.simulation.method;
  config.threads = options.threads;
  config.force = options.force;
  const ParticleModel model = build_particle_model(scene);
  const TimeStep ts = estimate_time_step(scene, model);
  const auto solver = make_solver(scene, model, ts, config);
  const auto free = static_cast<std::size_t>(
      std::count(model.motion.begin(), model.motion.end(), Motion::Free));
  const std::uint64_t scene_hash = scene_fingerprint(scene);
  const std::optional<ResumePoint> resume = restore(*solver, scene, config.precision, options);

  const std::int64_t last = scene.simulation.steps;
  const std::int64_t first = solver->step();
  const std::int64_t every = scene.output.every;
  const std::int64_t checkpoint_every = scene.output.checkpoint_every;
  std::FILE* log = options.log;
  if (log) {
    print_start(log, *solver, ts, free, config, last);
    if (resume)
      fmt::print(log, "continuing from {} at step {} (t = {:.6g} s)\n", *options.restart,
                 resume->step, resume->time);
    std::fflush(log);
  }

  OutputSet out(scene.output, scene.output.dir, scene.output.encoding, resume);
  Snapshot snap;
  Checkpoint checkpoint;
  auto emit = [&](std::int64_t step) {
    const bool frame = every > 0 && (step % every == 0 || step == last);
    solver->snapshot(snap, frame && scene.output.contacts);
    if (frame) out.write_frame(snap);
    out.log(snap);
    if (step == last) out.write_final(snap);
  };
  // The outputs of the state the solver holds now, without log rows or frames (which an
  // uninterrupted run would not have at this step): a checkpoint and final.csv.
  auto keep_state = [&](const fs::path& file) {
    save_checkpoint(*solver, config.precision, scene_hash, file, checkpoint);
    solver->snapshot(snap, false);
    out.write_final(snap);
  };

  RunSummary summary;
  ProgressBar bar(last, options.progress && is_terminal(stderr));
  const auto start = std::chrono::steady_clock::now();
  if (!resume) emit(0);
  if (resume && first == last) {  // nothing left to run: final.csv of the checkpoint's state
    solver->snapshot(snap, false);
    out.write_final(snap);
  }
  // Advance in chunks of about a tenth of a second between events, so that the progress
  // bar moves without a clock read in every step and an interruption is seen quickly.
  std::int64_t chunk = 1;
  while (solver->step() < last && !summary.interrupted_by) {
    const std::int64_t target = std::min(next_multiple(solver->step(), every, last),
                                         next_multiple(solver->step(), checkpoint_every, last));
    while (solver->step() < target) {
      if (options.interrupt && options.interrupt->load() != 0) {
        summary.interrupted_by = options.interrupt->load();
        break;
      }
      const auto t0 = std::chrono::steady_clock::now();
      const std::int64_t n = std::min(chunk, target - solver->step());
      try {
        solver->advance(n);
      } catch (const RunError& e) {
        // A blow-up: the solver holds the last good state; keep it for diagnosis or a restart.
        bar.finish();
        keep_state(last_good_file(scene));
        throw RunError(blow_up_message(e, solver->step(), scene));
      }
      const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (took < 0.05) chunk *= 2;
      else if (took > 0.2 && chunk > 1) chunk /= 2;
      bar.update(solver->step());
    }
    if (summary.interrupted_by) break;
    const std::int64_t step = solver->step();
    if (is_due(step, every) || step == last) emit(step);
    if (is_due(step, checkpoint_every) || (checkpoint_every > 0 && step == last))
      save_checkpoint(*solver, config.precision, scene_hash, checkpoint_file(scene), checkpoint);
  }
  bar.finish();
  if (summary.interrupted_by) {
    keep_state(checkpoint_file(scene));
    summary.checkpoint = checkpoint_file(scene).string();
  }
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
  if (log) {
    fmt::print(log, "{}: {} steps in {:.3f} s: {:.4g} steps/s, {:.4g} triangle-steps/s; "
               "outputs in {}\n",
               summary.interrupted_by ? "interrupted" : "done", summary.steps, seconds,
               summary.steps_per_second, summary.triangle_steps_per_second, scene.output.dir);
    std::fflush(log);
  }
  return summary;
}

}  // namespace tridem
