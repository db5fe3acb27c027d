#pragma once
// The subcommands of `tridem`; main.cpp only parses the command line and calls these.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tridem::app {

struct RunArgs {
  std::vector<std::string> command_line;  ///< argv as given, for the restart advice
  std::string scene;
  std::optional<std::string> out;
  std::optional<std::string> backend;
  std::optional<std::string> method;        ///< a spelling of kMethodNames
  std::optional<std::string> contact_test;  ///< a spelling of kContactTestNames
  bool no_bbox_prefilter = false;
  std::optional<std::int64_t> steps;
  std::optional<std::string> restart;  ///< checkpoint to continue from
  int threads = 0;
  std::optional<int> device;  ///< --device; unset: the first GPU (one rank) or the rank's own
  std::optional<std::string> particle_order;  ///< a spelling of kParticleOrderNames
  bool force = false;
  bool quiet = false;
  /// --live [PORT]: the live view (docs/live-view.md); empty text for the default port.
  std::optional<std::string> live;
  std::string live_host = "127.0.0.1";
  bool live_paused = false;
  int ranks = 1;  ///< MPI ranks of the job (mpirun -np N); above 1, src/mpi/ runs it
};
/// 0 when the run finished; 128 + the signal's number when SIGINT or SIGTERM stopped it
/// (after it wrote its checkpoint).
int run(const RunArgs&);

int info(const std::string& path);

struct RenderArgs {
  std::string input;  ///< a .vtu frame, or an output directory (its last frame)
  std::string out;    ///< PNG path; default next to the input
  std::string color = "speed";
  int width = 1200;
  std::string movie;  ///< --movie FILE.mp4: every frame of the directory, through ffmpeg
  int movie_fps = 25;
};
int render(const RenderArgs&);

struct ViewArgs {
  std::string dir;  ///< an output directory with frames/*.vtu
  std::string host = "127.0.0.1";
  int port = 8765;
};
/// Serves the live view's page over a finished run's frames until Ctrl-C.
int view(const ViewArgs&);

}  // namespace tridem::app
