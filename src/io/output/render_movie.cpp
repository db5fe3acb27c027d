// tridem render --movie: every frame to PNG (render_png), then the `ffmpeg` program turns
// them into an MP4. The program is started with an argument list (posix_spawnp), never
// through a shell, so no path is interpreted.
#include "io/output/step_files.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"
#include "tridem/render.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace tridem {

namespace {

namespace fs = std::filesystem;

/// Runs `args` (args[0] looked up on PATH) and returns its exit status; -1 when it could
/// not be started.
int run_program(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// Removes the movie's temporary folder however render_movie leaves.
struct TempFolder {
  fs::path path;
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

}  // namespace

Snapshot read_frame_to_render(const fs::path& vtu, const RenderOptions& options) {
  ArraySet<FrameArray> arrays;
  Snapshot s = read_vtu_frame(vtu, &arrays);
  if (options.color_by == RenderOptions::ColorBy::Speed && !arrays.has(FrameArray::Velocity))
    throw Error(fmt::format("{} has no velocity array (its run's [output] frame_arrays left it "
                            "out), so it cannot be coloured by speed: use --color material or "
                            "--color body",
                            vtu.string()));
  return s;
}

std::size_t render_movie(const fs::path& dir, const fs::path& mp4, const RenderOptions& options,
                         int fps) {
  const std::vector<fs::path> frames = io::kFrameFiles.all(dir, ".vtu");
  if (frames.empty())
    throw Error(fmt::format("{}: no frames/*.vtu here; run with [output] every > 0 to write "
                            "frames",
                            dir.string()));
  if (fps < 1 || fps > 120) throw Error(fmt::format("movie frame rate {} is outside 1..120", fps));
  // One speed range and one region for all frames: colours and picture do not jump.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::array<double, 4> region{lo, lo, -lo, -lo};
  for (const fs::path& f : frames) {
    const Snapshot s = read_frame_to_render(f, options);
    for (std::size_t k = 0; k < s.size(); ++k) {
      const double v = std::hypot(s.vx[k], s.vy[k]);
      if (s.motion[k] == Motion::Free && std::isfinite(v))
        lo = std::min(lo, v), hi = std::max(hi, v);
      for (auto [x, y] : {std::pair{s.x1[k], s.y1[k]}, {s.x2[k], s.y2[k]}, {s.x3[k], s.y3[k]}}) {
        if (!std::isfinite(x) || !std::isfinite(y)) continue;
        region[0] = std::min(region[0], x), region[1] = std::min(region[1], y);
        region[2] = std::max(region[2], x), region[3] = std::max(region[3], y);
      }
    }
  }
  RenderOptions o = options;
  if (!(lo <= hi)) lo = hi = 0;
  if (!o.speed_min) o.speed_min = lo;
  if (!o.speed_max) o.speed_max = hi;
  if (!o.region && region[0] < region[2] && region[1] < region[3]) o.region = region;

  std::error_code ec;
  TempFolder temp{fs::path(mp4).replace_filename(
      fmt::format(".{}.frames.{}", mp4.filename().string(), static_cast<long>(getpid())))};
  fs::create_directories(temp.path, ec);
  if (ec)
    throw Error(fmt::format("cannot write the movie's frames into {}: {}", temp.path.string(),
                            ec.message()));
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const Snapshot s = read_frame_to_render(frames[k], options);
    o.label = fmt::format("t = {:.4f} s   step {}", s.time, s.step);
    render_png(s, temp.path / fmt::format("frame_{:06d}.png", k), o);
  }
  // yuv420p (what players expect) needs even sides: pad by a pixel where one is odd.
  const int status = run_program(
      {"ffmpeg", "-y", "-loglevel", "error", "-framerate", std::to_string(fps), "-i",
       (temp.path / "frame_%06d.png").string(), "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white",
       "-c:v", "libx264", "-pix_fmt", "yuv420p", mp4.string()});
  if (status == -1)
    throw Error("tridem render --movie needs the ffmpeg program, which was not found on PATH "
                "(Debian: apt-get install ffmpeg)");
  if (status != 0)
    throw Error(fmt::format("ffmpeg failed (exit status {}) writing {}", status, mp4.string()));
  return frames.size();
}

}  // namespace tridem
