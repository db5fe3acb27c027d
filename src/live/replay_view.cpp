#include "live/replay_view.hpp"

#include "io/output/step_files.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"
#include "tridem/setting_names.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace tridem::live {

namespace fs = std::filesystem;

std::vector<fs::path> replay_frames(const fs::path& dir) {
  std::vector<fs::path> found = io::kFrameFiles.all(dir, ".vtu");
  if (found.empty())
    throw Error(fmt::format("{}: no frames/*.vtu here; run with [output] every > 0 to write "
                            "frames",
                            dir.string()));
  return found;
}

Snapshot read_replay_frame(const fs::path& vtu) {
  ArraySet<FrameArray> arrays;
  Snapshot s = read_vtu_frame(vtu, &arrays);
  // The view shows speeds and kinetic energy: zeros in their place would be wrong numbers.
  for (FrameArray a : {FrameArray::Velocity, FrameArray::AngularVelocity})
    if (!arrays.has(a))
      throw Error(fmt::format("{} has no {} array (its run's [output] frame_arrays left it out): "
                              "tridem view needs velocity and angular_velocity to show the "
                              "speeds and energies",
                              vtu.string(), name_in(kFrameArrayNames, a)));
  return s;
}

void angles_from_vertices(const Snapshot& first, Snapshot& snap) {
  const std::size_t n = std::min(first.size(), snap.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double ax = first.x1[i] - first.x[i], ay = first.y1[i] - first.y[i];
    const double bx = snap.x1[i] - snap.x[i], by = snap.y1[i] - snap.y[i];
    snap.theta[i] = first.theta[i] + std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }
}

ReplayView::ReplayView(const fs::path& dir, const LiveOptions& options, std::FILE* log)
    : files_(replay_frames(dir)), log_(log), first_(read_replay_frame(files_.front())) {
  geometry_ = std::make_shared<const std::string>(encode_geometry(first_));
  server_ = std::make_unique<LiveServer>(options.host, options.port,
                                         static_cast<LiveServer::Events&>(*this), log);
  if (log_) {
    fmt::print(log_, "replay of {} frame{} of {} on http://{}:{}/ (Ctrl-C to stop)\n",
               files_.size(), files_.size() == 1 ? "" : "s", dir.string(), options.host,
               server_->port());
    std::fflush(log_);
  }
}

// As LiveView: the thread stopped while server_ is still there for its last tasks.
ReplayView::~ReplayView() { server_->stop(); }

void ReplayView::opened(int client) {
  clients_[client] = Client{};
  server_->send(client, geometry_, true);
  server_->send(
      client,
      std::make_shared<const std::string>(fmt::format(
          R"({{"state":{{"paused":true,"fps":10,"ended":false,"replay":{}}}}})", files_.size())),
      false);
}

void ReplayView::send_frame(int client, std::size_t index) {
  Snapshot snap;
  try {
    snap = read_replay_frame(files_[index]);
  } catch (const Error& e) {
    if (log_) fmt::print(log_, "live: {}\n", e.what());
    return;
  }
  if (snap.size() != first_.size()) {
    if (log_)
      fmt::print(log_, "live: {} has {} triangles, the first frame {}: skipped\n",
                 files_[index].string(), snap.size(), first_.size());
    return;
  }
  angles_from_vertices(first_, snap);
  fill_frame(snap, compute_energy(snap), frame_);
  server_->send(client, std::make_shared<const std::string>(encode_stats(frame_, true, 10)), false);
  server_->send(client, std::make_shared<const std::string>(encode_frame(frame_)), true);
}

void ReplayView::received(int client, const ClientMessage& m) {
  // The page plays a replay by seeking frame after frame; "next" (a client that drew
  // its frame) brings only the first one, "step" the following one.
  using K = ClientMessage::Kind;
  Client& c = clients_[client];
  if (m.kind == K::Seek) {
    c.at = std::min<std::size_t>(static_cast<std::size_t>(m.value), files_.size() - 1);
  } else if (m.kind == K::Step) {
    c.at = std::min(c.at + 1, files_.size() - 1);
  } else if (m.kind != K::Next || c.sent) {
    return;  // pause, resume, fps: the page's own playback
  }
  c.sent = true;
  send_frame(client, c.at);
}

void ReplayView::closed(int client) { clients_.erase(client); }

}  // namespace tridem::live
