#pragma once
// tridem view OUTDIR: the live view's page over a finished run's frames (frames/*.vtu),
// with a time slider. Each client asks for a frame by its index ("seek N"); the server
// reads it, turns it into the live wire format and sends it.
#include "live/frame_encoder.hpp"
#include "live/live_server.hpp"
#include "live/live_view.hpp"

#include <filesystem>
#include <map>
#include <memory>
#include <vector>

namespace tridem::live {

/// The frames of an output directory, in step order. Throws Error when there are none.
std::vector<std::filesystem::path> replay_frames(const std::filesystem::path& dir);
/// One frame to replay; refuses (Error) a frame written without the velocities the view
/// shows (`[output] frame_arrays`).
Snapshot read_replay_frame(const std::filesystem::path& vtu);

/// Frames read from .vtu files carry no angle (read_vtu_frame gives 0): the angle of each
/// triangle from how its first vertex turned about its centroid since `first`.
void angles_from_vertices(const Snapshot& first, Snapshot& snap);

class ReplayView final : private LiveServer::Events {
 public:
  ReplayView(const std::filesystem::path& dir, const LiveOptions& options, std::FILE* log);
  ~ReplayView() override;
  ReplayView(const ReplayView&) = delete;
  ReplayView& operator=(const ReplayView&) = delete;
  unsigned short port() const { return server_->port(); }
  std::size_t frames() const { return files_.size(); }

 private:
  void opened(int client) override;
  void received(int client, const ClientMessage& message) override;
  void closed(int client) override;
  void send_frame(int client, std::size_t index);

  std::vector<std::filesystem::path> files_;
  std::vector<double> times_;
  std::FILE* log_;
  Snapshot first_;
  LiveServer::Message geometry_;
  FrameData frame_;
  struct Client {
    std::size_t at = 0;  ///< the frame it shows
    bool sent = false;   ///< whether it has had one
  };
  std::map<int, Client> clients_;
  std::unique_ptr<LiveServer> server_;
};

}  // namespace tridem::live
