#include "tridem/run.hpp"

#include "core/progress.hpp"
#include "core/solver_factory.hpp"
#include "tridem/output.hpp"

#include <algorithm>
#include <chrono>
#include <fmt/format.h>

namespace tridem {

namespace {

/// The next step at or after `step` where something is written.
std::int64_t next_output(std::int64_t step, std::int64_t every, std::int64_t last) {
  if (every <= 0) return last;
  return std::min(last, (step / every + 1) * every);
}

}  // namespace

RunSummary run_scene(const Scene& input, const RunOptions& options) {
  Scene scene = input;
  if (options.out_dir) scene.output.dir = *options.out_dir;
  if (options.backend) scene.simulation.backend = *options.backend;
  if (options.steps) scene.simulation.steps = *options.steps;
  if (options.method) scene.simulation.method = *options.method;
  if (options.contact_test) scene.simulation.contact_test = *options.contact_test;
  if (options.bbox_prefilter) scene.simulation.bbox_prefilter = *options.bbox_prefilter;

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

  const std::int64_t last = scene.simulation.steps;
  const std::int64_t every = scene.output.every;
  std::FILE* log = options.log;
  if (log) {
    fmt::print(log, "tridem {}: {} triangle{} ({} free), solver {}{}\n", TRIDEM_VERSION,
               solver->size(), solver->size() == 1 ? "" : "s", free, solver->description(),
               config.backend == Backend::Auto ? " (picked by backend = auto)" : "");
    fmt::print(log, "dt = {:.6g} s = {:.3g} x dt_crit ({:.6g} s){}, {} steps to t = {:.6g} s\n",
               solver->dt(), solver->dt() / ts.critical, ts.critical,
               ts.automatic ? ", automatic" : "", last,
               static_cast<double>(last) * solver->dt());
    std::fflush(log);
  }

  OutputSet out(scene.output, scene.output.dir, scene.output.encoding);
  Snapshot snap;
  auto emit = [&](std::int64_t step) {
    const bool frame = every > 0 && (step % every == 0 || step == last);
    solver->snapshot(snap, frame && scene.output.contacts);
    if (frame) out.write_frame(snap);
    out.log(snap);
    if (step == last) out.write_final(snap);
  };

  ProgressBar bar(last, options.progress && is_terminal(stderr));
  const auto start = std::chrono::steady_clock::now();
  emit(0);
  // Advance in chunks of about a tenth of a second between output steps, so that the
  // progress bar moves without a clock read in every step.
  std::int64_t chunk = 1;
  while (solver->step() < last) {
    const std::int64_t target = next_output(solver->step(), every, last);
    while (solver->step() < target) {
      const auto t0 = std::chrono::steady_clock::now();
      const std::int64_t n = std::min(chunk, target - solver->step());
      solver->advance(n);
      const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      // Capped: doubled unchecked at every fast chunk it overflowed after ~63 output
      // events and the loop stalled.
      if (took < 0.05) chunk = std::min<std::int64_t>(2 * chunk, std::int64_t{1} << 20);
      else if (took > 0.2 && chunk > 1) chunk /= 2;
      bar.update(solver->step());
    }
    emit(solver->step());
  }
  bar.finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  RunSummary summary;
  summary.steps = last;
  summary.triangles = solver->size();
  summary.seconds = seconds;
  summary.steps_per_second = seconds > 0 ? static_cast<double>(last) / seconds : 0;
  summary.triangle_steps_per_second =
      summary.steps_per_second * static_cast<double>(summary.triangles);
  summary.solver = solver->description();
  if (log) {
    fmt::print(log, "done: {} steps in {:.3f} s: {:.4g} steps/s, {:.4g} triangle-steps/s; "
               "outputs in {}\n",
               last, seconds, summary.steps_per_second, summary.triangle_steps_per_second,
               scene.output.dir);
    if (const std::string stats = solver->statistics(); !stats.empty())
      fmt::print(log, "{}: {}\n", solver->description(), stats);
    std::fflush(log);
  }
  return summary;
}

}  // namespace tridem
