#pragma once
// The live view of a running simulation (tridem run --live): the time loop's StepObserver
// on one side, the server's Events on the other.
//
// Stepping thread (after_step): returns at once unless a client wants a frame and the
// frame-rate limit allows one; then it takes a Snapshot, copies the poses and colour
// fields into the back buffer and swaps it with the front one (try_lock: when the server
// is still encoding the last frame, this one is dropped rather than waited for). While a
// client has paused the run it waits here, between steps, for resume or single step.
// Server thread: encodes the front buffer and sends it to each client that asked for a
// frame and is not still receiving the last one (a slow browser drops frames).
#include "live/frame_encoder.hpp"
#include "live/live_server.hpp"
#include "tridem/step_observer.hpp"
#include "tridem/vec2.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace tridem::live {

struct LiveOptions {
  std::string host = "127.0.0.1";
  unsigned short port = 8765;
  int fps = 30;  ///< the frame-rate limit at start; a client may change it
  /// Hold the run after its first step until a client resumes it (tridem run
  /// --live-paused): a look at the start before it moves on.
  bool start_paused = false;
};

class LiveView final : public StepObserver, private LiveServer::Events {
 public:
  /// Starts the server (throws tridem::Error when it cannot listen) and says its address
  /// on `log`.
  LiveView(const LiveOptions& options, Vec2d gravity, std::FILE* log);
  ~LiveView() override;
  LiveView(const LiveView&) = delete;
  LiveView& operator=(const LiveView&) = delete;

  unsigned short port() const { return server_->port(); }

  void after_step(const Solver& solver, const std::atomic<int>* interrupt) override;
  /// Sends the last state and tells the clients the run has ended.
  void run_ended(const Solver& solver) override;

 private:
  void opened(int client) override;
  void received(int client, const ClientMessage& message) override;
  void closed(int client) override;

  /// Stepping thread: a frame into the back buffer, swapped to the front (or dropped).
  void take_frame(const Solver& solver);
  bool frame_due() const;
  /// Server thread: the front frame to every client that asked for one.
  void deliver();
  void send_state(int client);
  void broadcast_state();

  Vec2d gravity_;
  std::FILE* log_;

  // Stepping thread only.
  Snapshot snap_;
  FrameData back_;
  std::chrono::steady_clock::time_point last_frame_{};
  bool geometry_taken_ = false;

  // Shared, under mutex_ (try_lock from the stepping thread).
  std::mutex mutex_;
  FrameData front_;
  bool front_fresh_ = false;
  LiveServer::Message geometry_;

  // Set by the server thread, read between steps.
  std::atomic<bool> wanted_{false};
  std::atomic<bool> paused_{false};
  std::atomic<int> step_credit_{0};
  std::atomic<int> fps_;
  std::atomic<bool> ended_{false};
  std::mutex wake_mutex_;
  std::condition_variable wake_;

  // Server thread only.
  struct Client {
    bool wants = false;
    bool has_geometry = false;
  };
  std::map<int, Client> clients_;

  /// Last: destroyed first, so that its thread has stopped before the rest goes.
  std::unique_ptr<LiveServer> server_;
};

}  // namespace tridem::live
