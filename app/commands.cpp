#include "commands.hpp"
#include "restart_command.hpp"

#include "core/numbering_note.hpp"
#include "interrupt.hpp"
#include "live/live_view.hpp"
#include "live/replay_view.hpp"
#include "tridem/bonds_reader.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"
#include "tridem/render.hpp"
#include "tridem/run.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/setting_names.hpp"

#include <chrono>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <thread>
#include <utility>
#ifdef TRIDEM_WITH_MPI
#include "mpi/mpi_run.hpp"
#endif

namespace tridem::app {

namespace fs = std::filesystem;

namespace {

/// The last frame of an output directory: the highest step among its frames.
fs::path last_frame(const fs::path& dir) {
  if (auto frame = last_frame_file(dir)) return *frame;
  throw Error(fmt::format("{}: no frames/*.vtu here; run with [output] every > 0 to write "
                          "frames, or give a .vtu file",
                          dir.string()));
}

/// What the command line says instead of the scene. main.cpp checked the spellings
/// against the same tables.
SceneOverrides overrides(const RunArgs& args) {
  SceneOverrides o;
  o.out_dir = args.out;
  if (args.backend) o.backend = value_in(kBackendNames, *args.backend);
  o.steps = args.steps;
  if (args.method) o.method = value_in(kMethodNames, *args.method);
  if (args.contact_test) o.contact_test = value_in(kContactTestNames, *args.contact_test);
  if (args.no_bbox_prefilter) o.bbox_prefilter = false;
  return o;
}

}  // namespace

int run(const RunArgs& args) {
  const auto started = std::chrono::steady_clock::now();
  auto read = [&] { return apply_overrides(read_scene(args.scene), overrides(args)); };
  RunOptions options;
  options.force = args.force;
  options.threads = args.threads;
  options.device = args.device.value_or(0);
  if (args.particle_order)
    options.particle_order =
        value_in(kParticleOrderNames, *args.particle_order).value_or(ParticleOrder::Auto);
  options.progress = !args.quiet;
  options.restart = args.restart;
  options.started = started;
  options.interrupt = &install_interrupt_handlers();
  auto report = [&](const RunSummary& summary) {
    if (!summary.interrupted_by) return 0;
    // The same command line, so that the restarted run has the same overrides: the
    // checkpoint refuses any other physics.
    const std::string same_run = restart_command(args.command_line, summary.checkpoint);
    fmt::print(
        stderr, "interrupted by {} at step {}: checkpoint written to {}\ncontinue with: {}\n",
        signal_name(summary.interrupted_by), summary.last_step, summary.checkpoint, same_run);
    return exit_code_for_signal(summary.interrupted_by);
  };
#ifdef TRIDEM_WITH_MPI
  if (args.ranks > 1) {
    if (args.live)
      throw Error(fmt::format("--live watches a run of one rank; this job has {} ranks: run it "
                              "without mpirun, or without --live",
                              args.ranks));
    // Each rank takes the GPU of its node-local rank (mpi/device_choice): one --device
    // for every rank would put them all on one GPU, or be silently overridden.
    if (args.device)
      throw Error(fmt::format("--device picks the GPU of a run of one rank; this job has {} "
                              "ranks, and each takes the GPU of its rank on its node "
                              "(docs/scaling.md): leave --device out",
                              args.ranks));
    // The ranks keep each sub-domain's particles in their own order (docs/scaling.md).
    if (options.particle_order == ParticleOrder::Place)
      throw Error(fmt::format("--particle-order place numbers the particles of a run of one "
                              "rank; this job has {} ranks, which keep their own order: leave "
                              "--particle-order out",
                              args.ranks));
    return mpi::run_on_ranks(read, options, report);
  }
#endif
  Scene scene = read();
  std::unique_ptr<live::LiveView> live_view;
  if (args.live) {
    live::LiveOptions lo;
    lo.host = args.live_host;
    lo.start_paused = args.live_paused;
    if (!args.live->empty()) lo.port = static_cast<unsigned short>(std::stoi(*args.live));
    live_view = std::make_unique<live::LiveView>(lo, scene.simulation.gravity, stdout);
    options.observer = live_view.get();
  }
  const RunSummary summary = run_scene(std::move(scene), options);
  live_view.reset();  // the last frame sent, the connections closed
  return report(summary);
}

int info(const std::string& path) {
  const Scene scene = read_scene(path);
  const SceneInfo info = describe_scene(scene);
  const auto& sim = scene.simulation;
  fmt::print("scene        {}\n", scene.source);
  fmt::print("triangles    {} ({} free, {} fixed, {} prescribed)\n", info.triangles, info.free,
             info.fixed, info.prescribed);
  fmt::print("materials    {}\n", scene.materials.size());
  for (const Material& m : scene.materials)
    fmt::print("  {:<12} density {:g} kg/m3, penalty {:g} Pa, tangential {:g} Pa, "
               "friction {:g}, {}\n",
               m.name, m.density, m.penalty, m.tangential_penalty, m.friction,
               m.restitution ? fmt::format("restitution {:g}", *m.restitution)
                             : fmt::format("damping {:g} (legacy)", m.damping));
  fmt::print("bounding box [{:g}, {:g}] x [{:g}, {:g}] m\n", info.box_lo.x, info.box_hi.x,
             info.box_lo.y, info.box_hi.y);
  fmt::print("longest edge {:g} m (free particles; the cell size)\n", info.longest_edge);
  fmt::print("dt critical  {:.6g} s{}\n", info.dt_critical,
             info.dt_limit.empty() ? "" : ", set by " + info.dt_limit);
  fmt::print("dt chosen    {:.6g} s ({}, {:.3g} x critical)\n", info.dt_chosen,
             info.dt_automatic ? fmt::format("automatic, safety {:g}", sim.safety) : "given",
             info.dt_chosen / info.dt_critical);
  fmt::print("steps        {} (t = {:.6g} s)\n", info.steps,
             static_cast<double>(info.steps) * info.dt_chosen);
  fmt::print("backend      {} -> {}, precision {}\n", backend_name(sim.backend),
             backend_name(resolve_backend(sim.backend)), precision_name(sim.precision));
  fmt::print("method       {}\n",
             method_description(sim.method, sim.contact_test, sim.bbox_prefilter));
  const PeriodicCell& cell = sim.periodic;
  if (cell.any())
    fmt::print("periodic     {}{}{}\n",
               cell.x ? fmt::format("x in [{:g}, {:g}) ", cell.x->lo, cell.x->hi) : "",
               cell.y ? fmt::format("y in [{:g}, {:g}) ", cell.y->lo, cell.y->hi) : "",
               cell.shear_rate != 0
                   ? fmt::format("Lees-Edwards shear rate {:g} 1/s", cell.shear_rate)
                   : "");
  fmt::print("measures     {}\n", scene.output.measures.size());
  for (const MeasureSpec& m : scene.output.measures) {
    const std::int64_t every = scene.output.measure_every(m);
    fmt::print("  {:<12} {} -> {}, {}\n", m.name,
               m.region ? fmt::format("region [{:g}, {:g}] x [{:g}, {:g}] m", m.region->lo.x,
                                      m.region->hi.x, m.region->lo.y, m.region->hi.y)
                        : std::string("the whole domain (every free particle)"),
               m.file_name(),
               every > 0 ? fmt::format("every {} steps", every) : std::string("last step only"));
  }
  fmt::print("pairs        about {} in the first list ({:.2f} a triangle: candidates within the "
             "skin)\n",
             info.first_list_pairs,
             info.triangles > 0
                 ? static_cast<double>(info.first_list_pairs) / static_cast<double>(info.triangles)
                 : 0.0);
  fmt::print("memory       about {:.1f} MiB (cpu and openmp backends)\n",
             static_cast<double>(info.memory_bytes) / (1024.0 * 1024.0));
  if (info.gpu_memory_bytes > 0)
    fmt::print("gpu memory   about {:.1f} MiB reserved by the cuda backend; GPU: {}\n",
               static_cast<double>(info.gpu_memory_bytes) / (1024.0 * 1024.0),
               info.gpu.empty() ? "none usable here" : info.gpu);
  // By place: consecutive ids a few grains apart, a small fraction of two random grains'
  // distance; at random, about that distance.
  fmt::print("numbering    ids i and i + 1 {:.3g} grain sizes apart on average, {:.2f} of two "
             "scrambled ids' distance ({})\n",
             info.numbering_distance, info.numbering_spread,
             info.triangles < kLargeNumbering
                 ? "a scene this small keeps its data in the caches whatever its order"
             // Bodies' members lie together whatever the bodies' order: the spread alone
             // would call a pile of polygons at random "by place".
             : info.numbered_by_place
                 ? "far apart: tridem run numbers them by place inside the solver, whose "
                   "outputs keep these ids"
             : info.numbering_spread < 0.25 ? "by place"
             : info.numbering_spread > 0.5
                 ? "at random: a large run steps at up to half the rate of the same grains "
                   "numbered by place"
                 : "partly by place");
  return 0;
}

int render(const RenderArgs& args) {
  const fs::path input = args.input;
  if (!args.movie.empty()) {
    if (!fs::is_directory(input))
      throw Error(fmt::format("--movie takes an output directory (with frames/*.vtu), not "
                              "the file '{}'",
                              input.string()));
    RenderOptions opt;
    opt.width = args.width;
    opt.color_by = value_in(kColorByNames, args.color).value_or(opt.color_by);
    const std::size_t frames = render_movie(input, args.movie, opt, args.movie_fps);
    fmt::print("{} ({} frames at {} per second)\n", args.movie, frames, args.movie_fps);
    return 0;
  }
  const fs::path frame = fs::is_directory(input) ? last_frame(input) : input;
  RenderOptions opt;
  opt.width = args.width;
  // main.cpp checked the spelling against the same table.
  opt.color_by = value_in(kColorByNames, args.color).value_or(opt.color_by);
  Snapshot snap = read_frame_to_render(frame, opt);
  // A bonded scene's frame has its bonds beside it: OUT/bonds/bonds_STEP.vtp.
  if (const std::string stem = frame.stem().string(); stem.rfind("frame_", 0) == 0) {
    const fs::path bonds =
        frame.parent_path().parent_path() / "bonds" / ("bonds_" + stem.substr(6) + ".vtp");
    if (fs::is_regular_file(bonds)) read_bonds_vtp(bonds, snap);
  }
  const fs::path out =
      args.out.empty() ? fs::path(frame).replace_extension(".png") : fs::path(args.out);
  render_png(snap, out, opt);
  fmt::print("{}\n", out.string());
  return 0;
}

int view(const ViewArgs& args) {
  live::LiveOptions lo;
  lo.host = args.host;
  lo.port = static_cast<unsigned short>(args.port);
  const std::atomic<int>& interrupt = install_interrupt_handlers();
  const live::ReplayView replay(args.dir, lo, stdout);
  while (interrupt.load() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  return 0;
}

}  // namespace tridem::app
