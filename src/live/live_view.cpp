#include "live/live_view.hpp"

#include "tridem/output.hpp"
#include "tridem/solver.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
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

// The server's thread stopped first, while server_ and the frames its last tasks use are
// still there (unique_ptr::reset would null server_ before the thread has stopped).
LiveView::~LiveView() { server_->stop(); }

bool LiveView::frame_due(Clock::time_point now) const {
  return now - last_frame_ >= std::chrono::microseconds(1'000'000 / fps_.load());
}

bool LiveView::frame_wanted() const {
  return wanted_.load(std::memory_order_relaxed) && !copying_.load(std::memory_order_relaxed);
}

std::int64_t LiveView::steps_before_look(std::int64_t steps, double seconds_per_step) {
  if (!prepared_ || paused_.load()) return 1;  // the first look after one step; a pause holds
  if (watchers_.load(std::memory_order_relaxed) == 0) return steps;  // the loop's own chunks
  // A client may send "next" or a control at any time: look again within kPollSeconds, and
  // at the due time of a wanted frame if it comes sooner.
  double look_in = kPollSeconds;
  if (frame_wanted()) {
    const auto interval = std::chrono::microseconds(1'000'000 / fps_.load());
    const double until =
        std::chrono::duration<double>(last_frame_ + interval - Clock::now()).count();
    look_in = std::clamp(until, 0.0, look_in);
  }
  if (seconds_per_step <= 0) return 1;
  return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::ceil(look_in / seconds_per_step)),
                                  1, steps);
}

void LiveView::after_advance(const Solver& solver, const std::atomic<int>* interrupt) {
  // The one look of an unwatched advance: two relaxed loads (no clock, no lock).
  if (!prepared_ || (frame_wanted() && frame_due(Clock::now()))) take_frame(solver);
  while (paused_.load()) {
    if (interrupt && interrupt->load() != 0) return;
    if (step_credit_.load() > 0) {
      step_credit_.fetch_sub(1);
      return;
    }
    if (frame_wanted() && frame_due(Clock::now())) take_frame(solver);
    std::unique_lock lock(wake_mutex_);
    wake_.wait_for(lock, std::chrono::milliseconds(20));
  }
}

void LiveView::prepare(const Solver& solver) {
  // The first look: one whole snapshot, for the triangles' shapes and what frames take
  // from the model (masses, motion, bonds' triangles), handed to the server's thread.
  auto first = std::make_shared<Snapshot>();
  solver.snapshot(*first, false);
  try {
    copy_ = solver.make_state_copy();
  } catch (const std::exception& e) {  // e.g. no GPU memory left for the staging
    if (log_) fmt::print(log_, "live: frames by snapshots ({})\n", e.what());
    copy_ = make_snapshot_copy(solver);
  }
  server_->post([this, first] {
    geometry_ = text(encode_geometry(*first));
    frame_state_ = std::move(*first);
  });
  prepared_ = true;
}

void LiveView::take_frame(const Solver& solver) {
  if (!prepared_) prepare(solver);
  if (copying_.exchange(true)) return;  // the server has not finished the last copy: drop
  copy_->start();
  last_frame_ = Clock::now();
  wanted_.store(false);  // convert() decides whether the next one is wanted
  server_->post([this] { convert(); });
}

void LiveView::convert() {
  try {
    const EnergyBudget budget = copy_->finish(frame_state_);
    copying_.store(false);  // frame_state_ is this thread's: the copy may start again
    fill_frame(frame_state_, compute_energy(frame_state_, gravity_, budget), frame_);
  } catch (const std::exception& e) {
    copying_.store(false);
    if (log_) fmt::print(log_, "live: frame dropped: {}\n", e.what());
    return;
  }
  newest_frame_ = std::make_shared<const std::string>(encode_frame(frame_));
  newest_stats_ = text(encode_stats(frame_, paused_.load(), fps_.load()));
  ++newest_;
  deliver();
}

void LiveView::deliver() {
  if (newest_ > 0) {
    for (auto& [id, client] : clients_) {
      if (!client.wants || client.sent >= newest_) continue;
      // Still receiving an earlier message: it gets the newest frame once it has asked
      // again (the last frame of the run goes to everyone).
      if (server_->queued(id) > 0 && !ended_.load()) continue;
      if (!client.has_geometry) {
        server_->send(id, geometry_, true);
        client.has_geometry = true;
      }
      server_->send(id, newest_stats_, false);
      server_->send(id, newest_frame_, true);
      client.wants = false;
      client.sent = newest_;
    }
  }
  update_wanted();
}

void LiveView::update_wanted() {
  // A client that has the newest frame will ask for a newer one: copy it now, so that it
  // is ready when it asks. One that asked and could not be sent it is tried again.
  bool want = false;
  for (const auto& entry : clients_)
    want = want || entry.second.wants || entry.second.sent >= newest_;
  wanted_.store(want);
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
  watchers_.store(static_cast<int>(clients_.size()));
  send_state(client);
  update_wanted();
}

void LiveView::received(int client, const ClientMessage& m) {
  using K = ClientMessage::Kind;
  switch (m.kind) {
    case K::Next:
      clients_[client].wants = true;
      deliver();
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
  watchers_.store(static_cast<int>(clients_.size()));
  update_wanted();
  // Nobody left to resume it: a run paused by a browser that has gone carries on.
  if (clients_.empty() && paused_.exchange(false)) {
    if (log_) {
      fmt::print(log_, "live: the last client has gone: the run resumes\n");
      std::fflush(log_);
    }
    wake_.notify_all();
  }
}

void LiveView::run_starting(const Solver& solver) { prepare(solver); }

void LiveView::run_ended(const Solver& solver) {
  // The last state to every client, whatever the frame rate, then the end.
  ended_.store(true);
  server_->post([this] {
    for (auto& entry : clients_) entry.second.wants = true;
  });
  // The server may still be converting the last copy (tens of ms at 10^6 triangles).
  for (int attempt = 0; attempt < 500 && copying_.load(); ++attempt)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  take_frame(solver);
  server_->post([this] { broadcast_state(); });
}

}  // namespace tridem::live
