#include "live/live_view.hpp"

#include "tridem/output.hpp"
#include "tridem/solver.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <thread>

namespace tridem::live {

namespace {

LiveServer::Message text(std::string s) {
  return std::make_shared<const std::string>(std::move(s));
}

}  // namespace

LiveView::LiveView(const LiveOptions& options, Vec2d gravity, std::FILE* log)
    : gravity_(gravity),
      log_(log),
      paused_(options.start_paused),
      fps_(std::clamp<int>(options.fps, kMinFps, kMaxFps)),
      server_(std::make_unique<LiveServer>(options.host, options.port,
                                           static_cast<LiveServer::Events&>(*this), log)) {
  if (log_) {
    fmt::print(log_, "live view on http://{}:{}/ (tridem serves it while the run lasts){}\n",
               options.host.find(':') == std::string::npos ? options.host
                                                           : "[" + options.host + "]",
               server_->port(),
               options.start_paused ? "; paused after the first step until resumed there" : "");
    std::fflush(log_);
  }
}

LiveView::~LiveView() { server_.reset(); }

bool LiveView::frame_due() const {
  const auto interval = std::chrono::microseconds(1'000'000 / fps_.load());
  return std::chrono::steady_clock::now() - last_frame_ >= interval;
}

void LiveView::after_step(const Solver& solver, const std::atomic<int>* interrupt) {
  // The one look of an unwatched step: a relaxed load each (no clock, no lock).
  if (!geometry_taken_ || (wanted_.load(std::memory_order_relaxed) && frame_due()))
    take_frame(solver);
  while (paused_.load()) {
    if (interrupt && interrupt->load() != 0) return;
    if (step_credit_.load() > 0) {
      step_credit_.fetch_sub(1);
      return;
    }
    if (wanted_.load() && frame_due()) take_frame(solver);
    std::unique_lock lock(wake_mutex_);
    wake_.wait_for(lock, std::chrono::milliseconds(20));
  }
}

void LiveView::take_frame(const Solver& solver) {
  solver.snapshot(snap_, false);
  fill_frame(snap_, compute_energy(snap_, gravity_, solver.energy()), back_);
  last_frame_ = std::chrono::steady_clock::now();
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;  // the server is encoding the last frame: drop this one
  if (!geometry_taken_) {
    geometry_ = std::make_shared<const std::string>(encode_geometry(snap_));
    geometry_taken_ = true;
  }
  std::swap(back_, front_);
  front_fresh_ = true;
  wanted_.store(false);
  lock.unlock();
  server_->post([this] { deliver(); });
}

void LiveView::deliver() {
  LiveServer::Message frame, stats, geometry;
  {
    std::lock_guard lock(mutex_);
    if (!front_fresh_) return;
    front_fresh_ = false;
    frame = std::make_shared<const std::string>(encode_frame(front_));
    stats = text(encode_stats(front_, paused_.load(), fps_.load()));
    geometry = geometry_;
  }
  bool still_wanted = false;
  for (auto& [id, client] : clients_) {
    if (!client.wants) continue;
    if (server_->queued(id) > 0) {  // still receiving an earlier message: drop this frame
      still_wanted = true;
      continue;
    }
    if (!client.has_geometry) {
      server_->send(id, geometry, true);
      client.has_geometry = true;
    }
    server_->send(id, stats, false);
    server_->send(id, frame, true);
    client.wants = false;
  }
  if (still_wanted) wanted_.store(true);
}

void LiveView::send_state(int client) {
  server_->send(client,
                text(fmt::format(R"({{"state":{{"paused":{},"fps":{},"ended":{}}}}})",
                                 paused_.load() ? "true" : "false", fps_.load(),
                                 ended_.load() ? "true" : "false")),
                false);
}

void LiveView::broadcast_state() {
  for (const auto& entry : clients_) send_state(entry.first);
}

void LiveView::opened(int client) {
  clients_[client] = Client{};
  send_state(client);
}

void LiveView::received(int client, const ClientMessage& m) {
  using K = ClientMessage::Kind;
  switch (m.kind) {
    case K::Next:
      clients_[client].wants = true;
      wanted_.store(true);
      break;
    case K::Pause: paused_.store(true); break;
    case K::Resume: paused_.store(false); break;
    case K::Step:
      if (paused_.load()) step_credit_.store(1);
      break;
    case K::Fps: fps_.store(static_cast<int>(m.value)); break;
    case K::Seek:
      if (log_)
        fmt::print(log_, "live: client {}: seek is for replays (tridem view); dropped\n", client);
      return;
    case K::Invalid: return;
  }
  wake_.notify_all();
  if (m.kind != K::Next) broadcast_state();
}

void LiveView::closed(int client) {
  clients_.erase(client);
  // Nobody left to resume it: a run paused by a browser that has gone carries on.
  if (clients_.empty() && paused_.exchange(false)) {
    if (log_) {
      fmt::print(log_, "live: the last client has gone: the run resumes\n");
      std::fflush(log_);
    }
    wake_.notify_all();
  }
}

void LiveView::run_ended(const Solver& solver) {
  // The last state to every client, whatever the frame rate, then the end.
  ended_.store(true);
  server_->post([this] {
    for (auto& entry : clients_) entry.second.wants = true;
  });
  for (int attempt = 0; attempt < 50; ++attempt) {  // the server may still be encoding
    {
      std::unique_lock lock(mutex_, std::try_to_lock);
      if (lock.owns_lock() && !front_fresh_) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  take_frame(solver);
  server_->post([this] { broadcast_state(); });
}

}  // namespace tridem::live
