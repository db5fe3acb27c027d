#pragma once
// The live view of a running simulation (tridem run --live): the time loop's StepObserver
// on one side, the server's Events on the other (docs/live-view.md, "How frames are
// taken").
//
// Stepping thread: the loop advances in its usual chunks while nobody watches; with a
// client connected, steps_before_look cuts them at the next frame's due time or every
// kPollSeconds (a "next" or a control is seen that soon), and while paused to one step.
// After an advance, when a frame is wanted, due by the frame-rate limit, and the server has
// finished with the last copy, it starts a StateCopy (the solver's state into buffers of
// the copy's own; on the GPU an asynchronous download) and posts the rest to the server:
// that is all a frame costs the stepping. While a client has paused the run it waits here,
// between steps, for resume or single step.
// Server thread: finishes the copy (waits for the download), converts it to the frame's
// floats, encodes it and sends the newest frame to each client that asked for one and is
// not still receiving the last one (a slow browser gets fewer frames, never old ones).
// Right after a client is sent a frame the next one is wanted, so that one is being copied
// and encoded while that client receives.
#include "live/frame_encoder.hpp"
#include "live/live_server.hpp"
#include "tridem/state_copy.hpp"
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

/// How often a watched run looks for a client's "next" or control at the most (the
/// chunks' length while a client is connected, unless a frame falls due sooner).
inline constexpr double kPollSeconds = 0.01;

class LiveView final : public StepObserver, private LiveServer::Events {
 public:
  /// Starts the server (throws tridem::Error when it cannot listen) and says its address
  /// on `log`.
  LiveView(const LiveOptions& options, Vec2d gravity, std::FILE* log);
  ~LiveView() override;
  LiveView(const LiveView&) = delete;
  LiveView& operator=(const LiveView&) = delete;

  unsigned short port() const { return server_->port(); }

  std::int64_t steps_before_look(std::int64_t steps, double seconds_per_step) override;
  void after_advance(const Solver& solver, const std::atomic<int>* interrupt) override;
  /// The first look, before the run's steps: the shapes and the staging of its copies
  /// (pinned memory on the GPU); frames come after steps, as before (a paused start holds
  /// after the first step). After the first step, as it was, the preparation counted
  /// against the stepping rate: at 10^6 triangles on the H200 a --live run without a
  /// client stepped 13 % slower than without --live over 6000 steps.
  void run_starting(const Solver& solver) override;
  /// Sends the last state and tells the clients the run has ended.
  void run_ended(const Solver& solver) override;
  /// Whether some client has asked for a frame newer than the last one taken: the next
  /// due look takes it. Read on any thread (the server's thread sets it).
  bool frame_wanted() const;

 private:
  using Clock = std::chrono::steady_clock;

  void opened(int client) override;
  void received(int client, const ClientMessage& message) override;
  void closed(int client) override;

  /// Stepping thread: the first look (geometry) and the copy of the state.
  void prepare(const Solver& solver);
  /// Stepping thread: starts a copy and hands it to the server, unless the server has
  /// not finished the last one (then this frame is dropped).
  void take_frame(const Solver& solver);
  bool frame_due(Clock::time_point now) const;
  /// Server thread: the copy finished, converted, encoded, delivered.
  void convert();
  /// Server thread: the newest frame to every client that asked and has not had it.
  void deliver();
  /// Server thread: wanted_ again when some client has the newest frame (it will ask for
  /// a newer one).
  void update_wanted();
  void send_state(int client);
  void broadcast_state();

  Vec2d gravity_;
  std::FILE* log_;

  // Stepping thread only (the copy is handed to the server by post, and back by copying_).
  std::unique_ptr<StateCopy> copy_;
  Clock::time_point last_frame_{};
  bool prepared_ = false;

  // Set by the server thread, read between steps.
  std::atomic<bool> copying_{false};  ///< a copy started and not yet finished by the server
  std::atomic<bool> wanted_{false};
  std::atomic<int> watchers_{0};  ///< clients connected
  std::atomic<bool> paused_{false};
  std::atomic<int> step_credit_{0};
  std::atomic<int> fps_;
  std::atomic<bool> ended_{false};
  std::mutex wake_mutex_;
  std::condition_variable wake_;

  // Server thread only (the first snapshot is handed over by post).
  Snapshot frame_state_;  ///< the copies land here; its model columns from the first look
  FrameData frame_;
  LiveServer::Message geometry_, newest_frame_, newest_stats_;
  std::int64_t newest_ = 0;  ///< frames converted so far: the newest one's number
  struct Client {
    bool wants = false;
    bool has_geometry = false;
    std::int64_t sent = 0;  ///< the number of the last frame it was sent
  };
  std::map<int, Client> clients_;

  /// Last: destroyed first, so that its thread has stopped before the rest goes.
  std::unique_ptr<LiveServer> server_;
};

}  // namespace tridem::live
