// tridem: the command line. Every failure, a usage error included, reaches the user as one
// "error: ..." message and exit code 1 (README.md).
#include "commands.hpp"
#include "startup_environment.hpp"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"

#ifdef TRIDEM_WITH_MPI
#include "mpi/mpi_world.hpp"
#endif

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fmt/format.h>
#include <string>
#include <vector>

namespace {

/// The spellings of a setting_names.hpp table, for CLI11's IsMember.
template <class Table>
std::vector<std::string> spelling_list(const Table& table) {
  std::vector<std::string> out;
  for (const auto& entry : table) out.emplace_back(entry.first);
  return out;
}

/// An existing file or folder, with the message a user can act on.
CLI::Validator existing(const char* what) {
  return CLI::Validator(
      [what](std::string& path) {
        std::error_code ec;
        return std::filesystem::exists(path, ec) ? std::string()
                                                 : fmt::format("no {} '{}' here", what, path);
      },
      "PATH");
}

/// A whole number of at least `least`, said without CLI11's range of doubles.
CLI::Validator at_least(long long least) {
  return CLI::Validator(
      [least](std::string& text) {
        long long v = 0;
        return CLI::detail::lexical_cast(text, v) && v >= least
                   ? std::string()
                   : fmt::format("must be a whole number of at least {}, got '{}'", least, text);
      },
      fmt::format("INT>={}", least));
}

/// A TCP port, or nothing (the option's default).
CLI::Validator port_number() {
  return CLI::Validator(
      [](std::string& text) {
        long long v = 0;
        return text.empty() || (CLI::detail::lexical_cast(text, v) && v >= 0 && v <= 65535)
                   ? std::string()
                   : fmt::format("must be a port number (0 to 65535), got '{}' (put --live "
                                 "after the scene file, or give it a port)",
                                 text);
      },
      "PORT");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tridem::app;
  restart_with_startup_environment(argv);
#ifdef TRIDEM_WITH_MPI
  // Under mpirun every rank runs this; only rank 0 prints errors (the ranks agree on them).
  const tridem::mpi::World world(argc, argv);
  const bool prints_errors = world.rank() == 0;
#else
  const bool prints_errors = true;
#endif
  CLI::App cli{"tridem: 2D discrete element simulation of triangular particles "
               "(Munjiza's potential contact force)", "tridem"};
  cli.set_version_flag("--version", std::string("tridem ") + TRIDEM_VERSION);
  cli.require_subcommand(1);

  RunArgs run_args;
  run_args.command_line.assign(argv, argv + argc);
#ifdef TRIDEM_WITH_MPI
  run_args.ranks = world.size();
#endif
  auto* run_cmd = cli.add_subcommand("run", "Run a scene and write its outputs");
  run_cmd->add_option("scene", run_args.scene, "Scene file (TOML)")->required()->check(existing("scene file"));
  run_cmd->add_option("--out", run_args.out, "Output directory (overrides [output] dir)");
  run_cmd
      ->add_option("--backend", run_args.backend,
                   "Overrides [simulation] backend: " + tridem::spellings_of(tridem::kBackendNames))
      ->check(CLI::IsMember(spelling_list(tridem::kBackendNames)));
  run_cmd->add_option("--method", run_args.method,
                      "Overrides [simulation] method: " + tridem::spellings_of(tridem::kMethodNames))
      ->check(CLI::IsMember(spelling_list(tridem::kMethodNames)));
  run_cmd->add_option("--contact-test", run_args.contact_test,
                      "Overrides [simulation] contact_test (single-domain, decomposition): " +
                          tridem::spellings_of(tridem::kContactTestNames))
      ->check(CLI::IsMember(spelling_list(tridem::kContactTestNames)));
  run_cmd->add_flag("--no-bbox-prefilter", run_args.no_bbox_prefilter,
                    "Sets [simulation] bbox_prefilter = false (single-domain, decomposition)");
  run_cmd->add_option("--steps", run_args.steps, "Number of steps (overrides [simulation] steps)")
      ->check(at_least(1));
  run_cmd->add_option("--threads", run_args.threads, "OpenMP threads (default: all cores)")
      ->check(at_least(0));
  run_cmd
      ->add_option("--device", run_args.device,
                   "GPU of the cuda backend, numbered from 0 (default 0)")
      ->check(at_least(0));
  run_cmd
      ->add_option("--particle-order", run_args.particle_order,
                   "The order the solver keeps the particles in (outputs always use the scene's "
                   "ids): " +
                       tridem::spellings_of(tridem::kParticleOrderNames) +
                       "; auto (the default) numbers a large scene by place when its ids lie "
                       "far apart, and again as a flow mixes its grains (docs/performance.md)")
      ->check(CLI::IsMember(spelling_list(tridem::kParticleOrderNames)));
  run_cmd->add_option("--restart", run_args.restart,
                      "Continue the run from a checkpoint (e.g. OUT/checkpoint.ckpt)")
      ->check(existing("checkpoint"));
  run_cmd->add_flag("--force", run_args.force, "Run even if dt is above the stability limit");
  run_cmd->add_flag("--quiet", run_args.quiet, "No progress bar");
  auto* live_opt =
      run_cmd
          ->add_option("--live", run_args.live,
                       "Serve a live view of the run in the browser on PORT (default 8765; "
                       "docs/live-view.md)")
          ->expected(0, 1)
          ->check(port_number());
  run_cmd
      ->add_option("--live-host", run_args.live_host,
                   "Address the live view listens on (default 127.0.0.1, this machine only)")
      ->needs(live_opt);
  run_cmd
      ->add_flag("--live-paused", run_args.live_paused,
                 "With --live: hold the run after its first step until the page resumes it")
      ->needs(live_opt);

  ViewArgs view_args;
  auto* view_cmd =
      cli.add_subcommand("view", "Serve the live view's page over a finished run's frames");
  view_cmd->add_option("dir", view_args.dir, "Output directory (with frames/*.vtu)")
      ->required()
      ->check(existing("output directory"));
  view_cmd->add_option("--port", view_args.port, "Port (default 8765)")
      ->check(CLI::Range(0, 65535));
  view_cmd->add_option("--host", view_args.host, "Address to listen on (default 127.0.0.1)");

  std::string info_scene;
  auto* info_cmd = cli.add_subcommand("info", "Describe a scene: particles, time step, memory");
  info_cmd->add_option("scene", info_scene, "Scene file (TOML)")->required()->check(existing("scene file"));

  RenderArgs render_args;
  auto* render_cmd = cli.add_subcommand("render", "Draw a frame to PNG");
  render_cmd->add_option("input", render_args.input,
                         "A frame (.vtu) or an output directory (its last frame)")
      ->required()->check(existing("frame or folder"));
  render_cmd->add_option("-o,--out", render_args.out, "PNG file (default: beside the frame)");
  render_cmd
      ->add_option("--color", render_args.color,
                   "Colour by: " + tridem::spellings_of(tridem::kColorByNames))
      ->check(CLI::IsMember(spelling_list(tridem::kColorByNames)));
  render_cmd->add_option("--width", render_args.width, "Image width in pixels")
      ->check(CLI::Range(16, 16384));
  render_cmd->add_option("--movie", render_args.movie,
                         "Every frame of the output directory to this MP4 (needs the ffmpeg "
                         "program), with time labels and one colour range");
  render_cmd->add_option("--fps", render_args.movie_fps, "Frames per second of the movie")
      ->check(CLI::Range(1, 120));

  try {
    cli.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    if (prints_errors)
      fmt::print(stderr, "error: {}\n(tridem --help lists the commands and options)\n", e.what());
    return 1;
  }
  try {
    if (*run_cmd) return run(run_args);
    if (*info_cmd) return info(info_scene);
    if (*render_cmd) return render(render_args);
    if (*view_cmd) return view(view_args);
  } catch (const tridem::Error& e) {
    if (prints_errors) fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    if (prints_errors) fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  return 0;
}
